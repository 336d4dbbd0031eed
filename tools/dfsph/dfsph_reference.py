#!/usr/bin/env python3
"""Speed reference: SPlisHSPlasH's DFSPH on its bundled 2D dam break.

Runs the scene DamBreakModel_2D.json that ships with the PyPI package
`pysplishsplash` (2.19.0) headless, for a given simulated time, and measures
the wall time of the simulation loop only (initialisation, sampling and the
boundary volume map are not timed). The result is the speed reference for our
own solver.

The bundled scene is never edited: a modified copy (absolute model path,
optional particle radius, all exports off) is written to a temporary
directory, which also receives SPlisHSPlasH's cache/log output and is deleted
afterwards. Nothing is written into this repository.

Setup (once):
    python3 -m venv /opt/dfsph-venv
    /opt/dfsph-venv/bin/pip install pysplishsplash==2.19.0

Run (the package needs libGLdispatch preloaded to import):
    LD_PRELOAD=/lib/x86_64-linux-gnu/libGLdispatch.so.0 \
        /opt/dfsph-venv/bin/python tools/dfsph/dfsph_reference.py --seconds 0.5

Last line printed (machine-readable):
    dfsph particles=N simulated_s=S wall_s=W wall_per_simulated_s=X steps=K
"""

import argparse
import json
import os
import shutil
import sys
import tempfile
import time

import pysplishsplash as sph

SCENE_NAME = "DamBreakModel_2D.json"


def bundled_scene():
    """The package installs its data next to the interpreter: <venv>/bin/data."""
    candidates = [
        os.path.join(os.path.dirname(sys.executable), "data", "Scenes", SCENE_NAME),
        os.path.join(sys.prefix, "bin", "data", "Scenes", SCENE_NAME),
    ]
    for path in candidates:
        if os.path.isfile(path):
            return path
    sys.exit("cannot find %s (looked in: %s)" % (SCENE_NAME, ", ".join(candidates)))


def write_scene_copy(src, out_dir, particle_radius):
    """Copy the scene into out_dir with exports off and model paths absolute."""
    with open(src) as f:
        scene = json.load(f)
    src_dir = os.path.dirname(os.path.abspath(src))

    config = scene.setdefault("Configuration", {})
    config["pause"] = False
    for key in ("enablePartioExport", "enableVTKExport",
                "enableRigidBodyExport", "enableRigidBodyVTKExport",
                "enableStateExport"):
        config[key] = False
    if particle_radius is not None:
        config["particleRadius"] = particle_radius

    for body in scene.get("RigidBodies", []):
        geom = body.get("geometryFile")
        if geom and not os.path.isabs(geom):
            body["geometryFile"] = os.path.normpath(os.path.join(src_dir, geom))

    dst = os.path.join(out_dir, os.path.basename(src))
    with open(dst, "w") as f:
        json.dump(scene, f, indent=2)
    return dst, config


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=0.5,
                        help="simulated time to run (default 0.5)")
    parser.add_argument("--particle-radius", type=float, default=None,
                        help="override the scene's particleRadius (default: keep 0.025)")
    parser.add_argument("--scene", default=None,
                        help="scene JSON (default: the bundled %s)" % SCENE_NAME)
    args = parser.parse_args()

    src = os.path.abspath(args.scene) if args.scene else bundled_scene()
    work_dir = tempfile.mkdtemp(prefix="dfsph_reference_")
    try:
        scene_file, config = write_scene_copy(src, work_dir, args.particle_radius)

        base = sph.Exec.SimulatorBase()
        base.init(sceneFile=scene_file, useCache=False, outputDir=work_dir,
                  initialPause=False, useGui=False, stopAt=args.seconds)
        base.initSimulation()

        sim = sph.Simulation.getCurrent()
        particles = sum(sim.getFluidModel(i).numActiveParticles()
                        for i in range(sim.numberOfFluidModels()))
        tm = sph.TimeManager.getCurrent()
        method = sim.getValueInt(sph.Simulation.SIMULATION_METHOD)
        print("scene=%s particleRadius=%g simulationMethod=%d (4 = DFSPH) particles=%d"
              % (src, sim.getParticleRadius(), method, particles), flush=True)

        # Timed part: the simulation loop only. runSimulation() first does
        # SPlisHSPlasH's deferred initialisation (boundary data) and then
        # loops timeStepNoGUI() until stopAt. The per-step callback marks the
        # end of every step; the clock starts at the end of the first step,
        # so initialisation (and that one warm-up step) is not timed.
        marks = []  # (wall clock, simulated time) at the end of each step

        def on_step():
            marks.append((time.perf_counter(), tm.getTime()))

        base.setTimeStepCB(on_step)
        base.runSimulation()
        if len(marks) < 2:
            sys.exit("fewer than two time steps ran; increase --seconds")
        (wall0, sim0), (wall1, sim1) = marks[0], marks[-1]
        wall, simulated, steps = wall1 - wall0, sim1 - sim0, len(marks) - 1

        base.cleanup()
    finally:
        shutil.rmtree(work_dir, ignore_errors=True)

    print("dfsph particles=%d simulated_s=%.6g wall_s=%.6g wall_per_simulated_s=%.6g steps=%d"
          % (particles, simulated, wall, wall / simulated if simulated > 0 else float("nan"),
             steps))


if __name__ == "__main__":
    main()
