#!/usr/bin/env python3
"""The surface level of a 2D pool at rest over time, from liquid_run's particle dumps.

    python3 tools/liquid_validate/pool_level.py SCENE.json 1,5,20 [--layers] [--speeds]
        [--set KEY=VALUE ...] [--liquid-run build/bin/liquid_run]

Runs the scene to each time (from its start, each run deterministic) and prints the free surface's
height away from the walls: the top particle of each column two particle spacings wide in the middle
80 % of the tank, averaged, plus half a spacing. With --layers also the particles' layers (heights
in the middle 80 % split where they are more than a quarter spacing apart): how many particles
each holds and the gaps between them in spacings, from the floor up. With --speeds where the motion
is: per grid cell of depth below the top particle (the cell size from liquid_run's header), the
particles' rms speed, their mean vertical velocity and the share of the kinetic energy, so a pool
that keeps moving shows whether it churns at its surface or throughout. docs/physics.md ("Still
water that keeps its volume") quotes it.
"""
import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read_particles(dump):
    """The dump's particles as (x, y, vx, vy), read once for every measure below."""
    return [(float(r["x"]), float(r["y"]), float(r["vx"]), float(r["vy"])) for r in csv.DictReader(open(dump))]


def level(particles, length, spacing):
    # The columns tile the middle 80 % exactly (an edge column cut to a sliver can be left empty).
    start, width = 0.1 * length, 0.8 * length
    columns = int(width / (2 * spacing))
    top = [-1.0] * columns
    for x, y, _, _ in particles:
        if start < x < start + width:
            c = min(columns - 1, int((x - start) / width * columns))
            top[c] = max(top[c], y)
    tops = [t for t in top if t > 0.0]
    if not tops:
        sys.exit("pool_level: no particles in the middle of the tank")
    return statistics.mean(tops) + 0.5 * spacing


def layers(particles, length, spacing):
    heights = sorted(y for x, y, _, _ in particles if 0.1 * length < x < 0.9 * length)
    groups = [[heights[0]]] if heights else []
    for y in heights[1:]:
        if y - groups[-1][-1] > 0.25 * spacing:
            groups.append([y])
        else:
            groups[-1].append(y)
    means = [statistics.mean(g) for g in groups]
    counts = " ".join(str(len(g)) for g in groups)
    gaps = " ".join(f"{(b - a) / spacing:.2f}" for a, b in zip(means, means[1:]))
    return f"  {len(groups)} layers of {counts} particles; gaps / spacing: {gaps}"


def speeds(particles, cell, rows=8):
    top = max(y for _, y, _, _ in particles)
    total = sum(vx * vx + vy * vy for _, _, vx, vy in particles) or 1.0
    lines = []
    for k in range(rows):
        last = k == rows - 1
        band = [(vx, vy) for _, y, vx, vy in particles if (last or y > top - (k + 1) * cell) and y <= top - k * cell]
        if not band:
            continue
        squares = sum(vx * vx + vy * vy for vx, vy in band)
        rms = (squares / len(band)) ** 0.5
        rising = statistics.mean(vy for _, vy in band)
        depth = f"{k} to {k + 1}" if not last else f"{k} to the floor"
        lines.append(f"  cells {depth} below the top: {len(band):5d} particles, rms speed {rms * 1000:6.2f} mm/s, "
                     f"mean vertical {rising * 1000:+6.2f} mm/s, {squares / total:4.0%} of the kinetic energy")
    return "\n".join(lines)


def cell_size(stdout):
    match = re.search(r"h = ([0-9.eE+-]+) m", stdout)
    if not match:
        sys.exit("pool_level: liquid_run printed no cell size")
    return float(match.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("times", help="comma-separated simulated times, s")
    parser.add_argument("--layers", action="store_true", help="also print the particles' layers")
    parser.add_argument("--speeds", action="store_true", help="also print the particles' speeds by depth")
    parser.add_argument("--set", action="append", default=[], help="a scene override for liquid_run")
    parser.add_argument("--liquid-run", default=os.path.join(ROOT, "build", "bin", "liquid_run"))
    args = parser.parse_args()
    scene = json.load(open(args.scene))
    if scene.get("dimension") != 2:
        sys.exit("pool_level: a 2D scene")
    times = [float(t) for t in args.times.split(",")]
    with tempfile.TemporaryDirectory() as folder:
        dump = os.path.join(folder, "particles.csv")
        for t in times:
            overrides = [item for kv in args.set for item in ("--set", kv)]
            run = subprocess.run([args.liquid_run, args.scene, "--seconds", str(t), "-r", "1000000",
                                  "--dump-particles", dump] + overrides, capture_output=True, text=True)
            if run.returncode != 0:
                sys.exit(f"pool_level: liquid_run failed at {t} s:\n{run.stderr[-2000:]}")
            particles = read_particles(dump)
            height = level(particles, scene["domain"][0], scene["particle_spacing"])
            print(f"t = {t:g} s: surface {height * 1000:.2f} mm", flush=True)
            if args.layers:
                print(layers(particles, scene["domain"][0], scene["particle_spacing"]), flush=True)
            if args.speeds:
                print(speeds(particles, cell_size(run.stdout)), flush=True)


if __name__ == "__main__":
    main()
