#!/usr/bin/env python3
"""Side by side: this project's solver against SPlisHSPlasH's DFSPH on the same 2D dam break.

The scene is SPlisHSPlasH's DamBreakModel_2D at 64,516 particles (a 1.5 m square column, 2.5 cm
off the floor and the left wall of a 4 m square tank); assets/scenes/dam_break_tank_2d.json is the
same column, lattice and tank for liquid_run. The two run alternately, each over the same
simulated time, and each is timed over its steps alone (setup excluded). The machine's speed
drifts over hours, so only the ratio of runs made in one sitting means anything.

    python3 tools/dfsph/compare_dfsph.py                 # 1 s simulated, two rounds
    python3 tools/dfsph/compare_dfsph.py --seconds 2 --rounds 3

DFSPH comes from PyPI (`pysplishsplash` 2.19.0) in a virtual environment; --install creates it.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # the repository
VENV = "/opt/dfsph-venv"
DFSPH_RADIUS = 0.0029412  # 254 x 254 particles in the 1.5 m column: 64,516
SCENE = os.path.join(ROOT, "assets", "scenes", "dam_break_tank_2d.json")


def gl_dispatch():
    """pysplishsplash links libGLdispatch, which must be preloaded to import here."""
    for folder in ("/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu", "/lib/aarch64-linux-gnu",
                   "/usr/lib/aarch64-linux-gnu"):
        path = os.path.join(folder, "libGLdispatch.so.0")
        if os.path.exists(path):
            return path
    sys.exit("compare_dfsph: libGLdispatch.so.0 not found (apt-get install libglvnd0)")


def install():
    subprocess.run([sys.executable, "-m", "venv", VENV], check=True)
    subprocess.run([os.path.join(VENV, "bin", "pip"), "install", "-q", "pysplishsplash==2.19.0"], check=True)


def run_dfsph(seconds):
    env = dict(os.environ, LD_PRELOAD=gl_dispatch())
    out = subprocess.run([os.path.join(VENV, "bin", "python"), os.path.join(ROOT, "tools", "dfsph", "dfsph_reference.py"),
                          "--seconds", str(seconds), "--particle-radius", str(DFSPH_RADIUS)],
                         env=env, capture_output=True, text=True)
    m = re.search(r"dfsph particles=(\d+) simulated_s=(\S+) wall_s=(\S+) wall_per_simulated_s=(\S+) steps=(\d+)",
                  out.stdout)
    if out.returncode != 0 or not m:
        sys.exit("compare_dfsph: DFSPH run failed:\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return int(m[1]), float(m[4]), int(m[5])


def run_ours(tool, seconds):
    out = subprocess.run([tool, SCENE, "--seconds", str(seconds), "-r", "1000000"], capture_output=True, text=True)
    m = re.search(r"wall time of the steps: (\S+) s for (\S+) simulated s in (\d+) steps: (\S+) s per simulated second",
                  out.stdout)
    n = re.search(r"2D, (\d+) particles", out.stdout)
    if out.returncode != 0 or not m or not n:
        sys.exit("compare_dfsph: liquid_run failed:\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return int(n[1]), float(m[4]), int(m[3])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=1.0, help="simulated time of each run (default 1)")
    parser.add_argument("--rounds", type=int, default=2, help="alternating rounds (default 2)")
    parser.add_argument("--liquid-run", default=os.path.join(ROOT, "build", "bin", "liquid_run"))
    parser.add_argument("--install", action="store_true", help=f"create {VENV} with pysplishsplash first")
    args = parser.parse_args()
    if args.install:
        install()
    if not os.path.exists(os.path.join(VENV, "bin", "python")):
        sys.exit(f"compare_dfsph: no {VENV}; run with --install (needs PyPI)")
    if not os.access(args.liquid_run, os.X_OK):
        sys.exit(f"compare_dfsph: {args.liquid_run} not built (cmake --build --preset default)")

    ours, theirs = [], []
    for r in range(args.rounds):
        n, per_s, steps = run_dfsph(args.seconds)
        theirs.append(per_s)
        print(f"round {r + 1}: DFSPH        {n} particles, {steps} steps, {per_s:8.2f} wall s per simulated s", flush=True)
        n, per_s, steps = run_ours(args.liquid_run, args.seconds)
        ours.append(per_s)
        print(f"round {r + 1}: liquid_run   {n} particles, {steps} steps, {per_s:8.2f} wall s per simulated s", flush=True)
    a, b = statistics.median(ours), statistics.median(theirs)
    print(f"median over {args.rounds} rounds of {args.seconds:g} simulated s: liquid_run {a:.2f}, DFSPH {b:.2f} "
          f"wall s per simulated s; ratio {a / b:.3f}")


if __name__ == "__main__":
    main()
