#!/usr/bin/env python3
"""Surge-front reference: SPlisHSPlasH's DFSPH on Martin & Moyce's (1952) collapsing column.

Measures where DFSPH (PyPI package `pysplishsplash` 2.19.0) puts the surge
front of a collapsing 2D water column and compares it with Martin & Moyce's
experiment (column width a, height 2a), as an independent reference for our
own solver.

Scene (written to a temporary directory, deleted afterwards; nothing is
written into this repository):
  * 2D DFSPH (simulationMethod 4), gravity -9.81, density 1000, CFL-adaptive
    time steps, solver and boundary settings as in the bundled
    DamBreakModel_2D.json (volume-map walls, Bender et al. 2019).
  * Tank: UnitBox.obj scaled to [0.6, 0.3, 1] and translated to
    [0.3, 0.15, 0], used as a wall (mapInvert), so it spans x in [0, 0.6],
    y in [0, 0.3]. The volume-map resolution is chosen so that one map cell
    is about one kernel support radius (4 particle radii).
  * Water column: a = 0.1 m wide, 0.2 m high (50 x 100 particles at
    r = 1 mm), on the floor against the left wall. SPlisHSPlasH's FluidBlocks
    (denseMode 0) put the first particle centre one particle diameter inside
    the block's "start" corner, so the block is given as start = (-r, -r),
    end = (a + r, 2a + r), which alone would put the centres on r, 3r, ...,
    a - r. That is too close: the volume-map wall sits 0.5 r inside the mesh
    and the particles next to wall and floor would start at ~1.68 rho0. The block is therefore translated by OFFSET = 1.2 r in x and
    y, the placement at which the wall and floor particles start at rest
    density (997 vs 1001 inside; 1.0 r gives 1100, 1.25 r gives 978). The
    first particle centres are at 2.2 r from wall and floor (the bundled
    scene uses 3 r: its block is offset by one diameter plus its 0.5-diameter
    translation). The column keeps its width a; its initial front (particle
    centre) is at a + 0.2 r. The script prints the min/max coordinates.
  * Time step: CFL as in the bundled scene (cflMethod 1, cflFactor 1), but
    the bundled cap cflMaxTimeStepSize = 5 ms (chosen for r = 25 mm) makes
    DFSPH hit its 100-iteration limit at r = 1 mm and blow up, so the cap is
    min(5 ms, r * 1 s/m) (1 ms at r = 1 mm; stable in tests), and, with the
    explicit "Standard viscosity" on, also at most 0.03 h^2 / nu (h = 4 r,
    the support radius), its diffusive stability limit: with the bundled
    nu = 0.01 m^2/s at r = 1 mm, steps of 1.6e-4 s and 1e-4 s blew up within
    3 ms, 4.8e-5 s (= 0.03 h^2/nu) was stable over the 12 ms tested. The CFL
    minimum step is lowered to 0.1 * the cap where needed. --max-dt
    overrides the cap.

Note: the bundled viscosity (nu = 0.01 m^2/s, plus micropolar vorticity) is
about 10^4 times water's and forces ~5,000 steps at r = 1 mm (several
minutes on 2 cores); use --inviscid or --viscosity 1e-6 for water-like runs.

Measured: after every time step (base.setTimeStepCB) the simulated time t and
the front x_front = the largest x over all fluid particle centres (read as a
numpy view of the fluid model's "position" field). At the end
Z = (x_front - x_left_wall) / a with x_left_wall = 0 is interpolated linearly
at the experimental times T = t * sqrt(2 g / a) and compared with the
Martin & Moyce points; printed: Z at each T, mean and max relative error
|Z - Z_exp| / Z_exp, particle count and wall time.

Setup (once):
    python3 -m venv /opt/dfsph-venv
    /opt/dfsph-venv/bin/pip install pysplishsplash==2.19.0

Run (the package needs libGLdispatch preloaded to import):
    LD_PRELOAD=/lib/x86_64-linux-gnu/libGLdispatch.so.0 \\
        /opt/dfsph-venv/bin/python tools/dfsph/dfsph_column.py \\
        [--particle-radius 0.001] [--viscosity NU | --inviscid] [--seconds 0.245]

Last line printed (machine-readable):
    dfsph_column particles=N radius=R viscosity=V mean_rel_err=E max_rel_err=M
        wall_s=W init_s=I steps=K max_sample_gap_s=G max_dt=D
"""

import argparse
import json
import math
import os
import shutil
import sys
import tempfile
import time

import numpy as np

from dfsph_scene import BUNDLED_CONFIG, G, Run, configuration_2d, tank_wall

A = 0.1           # column width [m]
H = 0.2           # column height [m]
TANK = (0.6, 0.3)  # tank width, height [m]; spans [0, 0.6] x [0, 0.3]
X_LEFT_WALL = 0.0
OFFSET = 1.2       # block translation off wall and floor, in particle radii

# Martin & Moyce (1952), column n^2 = 2: (T, Z) with T = t sqrt(2g/a), Z = x/a.
MARTIN_MOYCE = [
    (0.84, 1.22), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89), (1.83, 2.11),
    (1.98, 2.33), (2.20, 2.56), (2.32, 2.78), (2.51, 3.00), (2.65, 3.22),
    (2.83, 3.44), (2.98, 3.67), (3.11, 3.89), (3.33, 4.11),
]

# Solver, time-step and material settings of the bundled DamBreakModel_2D.json.
BUNDLED_MATERIAL = {
    "id": "Fluid",
    "density0": 1000,
    "viscosityMethod": 1,
    "vorticityMethod": 1,
    "Standard viscosity": {"viscosity": 0.01},
    "Bender et al. 2017": {"vorticity": 0.1, "viscosityOmega": 0.05,
                           "inertiaInverse": 0.5},
}


def max_time_step(radius, viscosity, inviscid, override):
    if override is not None:
        return override
    dt = min(BUNDLED_CONFIG["cflMaxTimeStepSize"], radius * 1.0)
    if not inviscid:
        nu = (viscosity if viscosity is not None
              else BUNDLED_MATERIAL["Standard viscosity"]["viscosity"])
        if nu > 0:
            dt = min(dt, 0.03 * (4.0 * radius) ** 2 / nu)
    return dt


def build_scene(out_dir, radius, viscosity, inviscid, seconds, max_dt):
    material = json.loads(json.dumps(BUNDLED_MATERIAL))
    if inviscid:
        material["viscosityMethod"] = 0
        material["vorticityMethod"] = 0
    elif viscosity is not None:
        material["Standard viscosity"]["viscosity"] = viscosity
    wall, map_res = tank_wall((TANK[0] / 2, TANK[1] / 2), TANK, radius)

    scene = {
        "Configuration": configuration_2d(radius, max_dt, seconds),
        "Materials": [material],
        "RigidBodies": [wall],
        # denseMode 0: centres at start + 2r*(1 + j), j < round(size/2r) - 1.
        "FluidBlocks": [{
            "denseMode": 0,
            # z: a thin slab (+-4r); 2D keeps a single layer at z = 0 (a
            # +-2r slab is reported as an empty block by 2.19.0).
            "start": [X_LEFT_WALL - radius, -radius, -4 * radius],
            "end": [X_LEFT_WALL + A + radius, H + radius, 4 * radius],
            "translation": [OFFSET * radius, OFFSET * radius, 0],
            "scale": [1, 1, 1],
        }],
    }
    path = os.path.join(out_dir, "MartinMoyceColumn_2D.json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
    return path, map_res


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particle-radius", type=float, default=0.001,
                        help="particle radius in m (default 0.001, i.e. 2 mm spacing)")
    visc = parser.add_mutually_exclusive_group()
    visc.add_argument("--viscosity", type=float, default=None,
                      help="'Standard viscosity' coefficient (default: the bundled "
                           "scene's 0.01, with its micropolar vorticity on)")
    visc.add_argument("--inviscid", action="store_true",
                      help="turn viscosity and vorticity off")
    parser.add_argument("--seconds", type=float, default=0.245,
                        help="simulated time (default 0.245, i.e. T = 3.43)")
    parser.add_argument("--max-dt", type=float, default=None,
                        help="cflMaxTimeStepSize (default: min(5 ms, r*1 s/m, "
                             "0.03 h^2/nu if viscous))")
    args = parser.parse_args()

    r = args.particle_radius
    t_scale = math.sqrt(2.0 * G / A)
    visc_label = ("off" if args.inviscid else
                  "%g+vorticity" % (args.viscosity if args.viscosity is not None
                                    else BUNDLED_MATERIAL["Standard viscosity"]["viscosity"]))

    work_dir = tempfile.mkdtemp(prefix="dfsph_column_")
    try:
        max_dt = max_time_step(r, args.viscosity, args.inviscid, args.max_dt)
        scene_file, map_res = build_scene(work_dir, r, args.viscosity,
                                          args.inviscid, args.seconds, max_dt)
        wall_init0 = time.perf_counter()
        run = Run(scene_file, work_dir, args.seconds)
        base, sim, tm, positions = run.base, run.sim, run.time, run.positions
        n = run.fluid.numActiveParticles()
        p0 = positions()
        print("particles=%d radius=%g viscosity=%s max_dt=%.3g map_resolution=%s "
              "x=[%.5f, %.5f] y=[%.5f, %.5f] method=%d (4 = DFSPH)"
              % (n, sim.getParticleRadius(), visc_label, max_dt, list(map_res),
                 p0[:, 0].min(), p0[:, 0].max(), p0[:, 1].min(), p0[:, 1].max(),
                 run.method()), flush=True)

        samples = [(tm.getTime(), float(p0[:, 0].max()))]
        wall_marks = []

        def on_step():
            samples.append((tm.getTime(), float(positions()[:, 0].max())))
            wall_marks.append(time.perf_counter())

        base.setTimeStepCB(on_step)
        wall_run0 = time.perf_counter()
        base.runSimulation()
        wall_end = time.perf_counter()
        base.cleanup()
    finally:
        shutil.rmtree(work_dir, ignore_errors=True)

    if len(samples) < 3:
        sys.exit("fewer than two time steps ran; increase --seconds")
    t = np.array([s[0] for s in samples])
    z = (np.array([s[1] for s in samples]) - X_LEFT_WALL) / A
    T = t * t_scale
    gap = float(np.max(np.diff(t)))
    # runSimulation() starts with the deferred boundary initialisation (the
    # volume map); the first step's callback marks its end.
    init_s = wall_marks[0] - wall_init0
    sim_wall = wall_end - wall_marks[0]

    print("T_end=%.3f Z(T=0)=%.4f steps=%d max_sample_gap=%.2e s"
          % (T[-1], z[0], len(samples) - 1, gap))
    print("%6s %7s %7s %8s" % ("T", "Z_exp", "Z_dfsph", "rel_err"))
    errs = []
    for T_exp, Z_exp in MARTIN_MOYCE:
        if T_exp > T[-1]:
            print("%6.2f %7.2f %7s %8s" % (T_exp, Z_exp, "-", "(not reached)"))
            continue
        Z_mod = float(np.interp(T_exp, T, z))
        errs.append(abs(Z_mod - Z_exp) / Z_exp)
        print("%6.2f %7.2f %7.3f %+8.3f" % (T_exp, Z_exp, Z_mod, (Z_mod - Z_exp) / Z_exp))
    mean_err = float(np.mean(errs)) if errs else float("nan")
    max_err = float(np.max(errs)) if errs else float("nan")
    print("dfsph_column particles=%d radius=%g viscosity=%s mean_rel_err=%.4f "
          "max_rel_err=%.4f wall_s=%.2f init_s=%.2f steps=%d max_sample_gap_s=%.2e "
          "max_dt=%.3g" % (n, r, visc_label, mean_err, max_err, sim_wall, init_s,
                           len(samples) - 1, gap, max_dt))


if __name__ == "__main__":
    main()
