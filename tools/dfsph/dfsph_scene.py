"""What the 2D DFSPH reference scripts (dfsph_column.py, dfsph_sloshing.py) share: the bundled
DamBreakModel_2D's solver settings, a 2D scene's configuration, a rectangular tank as a
volume-map wall, and starting SPlisHSPlasH's simulator on a scene file.

Imported from the scripts beside it; needs the venv's `pysplishsplash` and numpy.
"""
import os
import sys

import numpy as np
import pysplishsplash as sph

G = 9.81

# Solver, time-step and material settings of the bundled DamBreakModel_2D.json.
BUNDLED_CONFIG = {
    "cflMethod": 1,
    "cflFactor": 1,
    "cflMaxTimeStepSize": 0.005,
    "boundaryHandlingMethod": 2,
    "DFSPH": {
        "minIterations": 2,
        "maxIterations": 100,
        "maxError": 0.1,
        "maxIterationsV": 100,
        "maxErrorV": 0.1,
        "enableDivergenceSolver": True,
    },
}


def data_dir():
    """The package installs its data next to the interpreter: <venv>/bin/data."""
    for path in (os.path.join(os.path.dirname(sys.executable), "data"),
                 os.path.join(sys.prefix, "bin", "data")):
        if os.path.isfile(os.path.join(path, "models", "UnitBox.obj")):
            return path
    sys.exit("cannot find the pysplishsplash data folder (models/UnitBox.obj)")


def configuration_2d(radius, max_dt, seconds):
    """The bundled configuration for a 2D DFSPH run of `seconds` at particle radius `radius`, CFL
    steps capped at `max_dt`, with no export."""
    config = dict(BUNDLED_CONFIG)
    config.update({
        "pause": False,
        "sim2D": True,
        "particleRadius": radius,
        "simulationMethod": 4,
        "gravitation": [0, -G, 0],
        "cflMaxTimeStepSize": max_dt,
        "cflMinTimeStepSize": min(1e-4, 0.1 * max_dt),
        "stopAt": seconds,
        "enablePartioExport": False,
        "enableVTKExport": False,
        "enableRigidBodyExport": False,
        "enableRigidBodyVTKExport": False,
        "enableStateExport": False,
    })
    return config


def tank_wall(centre, size, radius):
    """UnitBox.obj scaled to `size` (x, y) about `centre`, a wall the liquid stays inside
    (mapInvert), and its volume map's resolution. The map: one cell per kernel support radius
    (4 r) in x and y over the tank enlarged by 4 support radii on every side; four cells in z put
    map nodes exactly on the 2D plane z = 0, with all nodes of the cells touching it inside the
    tank's z extent."""
    support = 4.0 * radius
    resolution = [int(np.ceil((size[0] + 8.0 * support) / support)),
                  int(np.ceil((size[1] + 8.0 * support) / support)), 4]
    wall = {
        "geometryFile": os.path.join(data_dir(), "models", "UnitBox.obj"),
        "translation": [centre[0], centre[1], 0],
        "rotationAxis": [1, 0, 0],
        "rotationAngle": 0,
        "scale": [size[0], size[1], 1],
        "isDynamic": False,
        "isWall": True,
        "mapInvert": True,
        "mapThickness": 0.0,
        "mapResolution": resolution,
    }
    return wall, resolution


class Run:
    """SPlisHSPlasH's simulator on `scene_file`, initialised (one fluid model), in `work_dir`."""

    def __init__(self, scene_file, work_dir, seconds):
        self.base = sph.Exec.SimulatorBase()
        self.base.init(sceneFile=scene_file, useCache=False, outputDir=work_dir,
                       initialPause=False, useGui=False, stopAt=seconds)
        self.base.initSimulation()
        self.sim = sph.Simulation.getCurrent()
        if self.sim.numberOfFluidModels() != 1:
            sys.exit("expected one fluid model, got %d" % self.sim.numberOfFluidModels())
        self.fluid = self.sim.getFluidModel(0)
        self.time = sph.TimeManager.getCurrent()

    def positions(self):
        """A zero-copy view of the particle positions (N x 3, float32)."""
        buf = np.asarray(self.fluid.getFieldBuffer("position"))
        return buf.reshape(-1, 3)[:self.fluid.numActiveParticles()]

    def method(self):
        return self.sim.getValueInt(sph.Simulation.SIMULATION_METHOD)
