#!/usr/bin/env python3
"""Sloshing reference: SPlisHSPlasH's DFSPH on the tank liquid_validate measures.

Runs the first sloshing mode of the tank in liquid/analysis/oscillation.h (the
one `liquid_validate --only sloshing` runs) in DFSPH (PyPI package
`pysplishsplash` 2.19.0) and measures its period and damping ratio the way
measure_oscillation() in liquid/analysis/oscillation.cpp does, as an
independent reference for our own solver's figures.

The tank: 2D, length L = 0.5 m, still depth h = 0.1 m, the surface starting
as the first mode eta(x) = A cos(pi x / L) with A = 0.01 m (--amplitude
changes it, to see whether the figures depend on it; the liquid rises
at x = 0 and falls at x = L), gravity 9.81 (the project's default; the
sloshing scene keeps it), density 1000. Linear theory:
omega^2 = g k tanh(k h), k = pi / L, T = 1.072 s.

Scene (written to a temporary directory, deleted afterwards; nothing is
written into this repository):
  * 2D DFSPH (simulationMethod 4), gravity -9.81, density 1000, CFL-adaptive
    time steps, solver and boundary settings as in the bundled
    DamBreakModel_2D.json (volume-map walls, Bender et al. 2019), as
    tools/dfsph/dfsph_column.py sets them.
  * Liquid: laid out like sloshing_scene() in oscillation.cpp, on the same
    lattice. The particle spacing is s = 2 r; --cells N gives the spacing of
    the project's 2D tank at N cells along L: sloshing_scene() keeps
    rest_pool_2d.json's particles per cell (spacing 0.5/117 m on cells of
    0.5/64 m), so s = (L / N) * 64/117, and the default N = 128 (the tank
    liquid_validate holds to its targets) is s = L / 234 = 2.137 mm,
    r = 1.068 mm (0.55 cells, not half a cell). --spacing sets s directly.
    The liquid is L / s particle columns whose centres sit at x_i = (i + 1/2) s
    and y = (j + 1/2) s, j < n_i, with n_i = max(1, round(surface_i / s))
    layers, surface_i = h + A cos(pi x_i / L) over the column's centre (the
    C++'s whole number of layers nearest the surface). The C++ gives each
    column its own block; SPlisHSPlasH 2.19.0 reports a FluidBlock less than
    two particles wide as empty (createFluidBlocks(): stepsX <= 1), so each
    run of neighbouring columns with the same n_i is one block instead (the
    same particles: n_i changes by at most one every ~16 columns at any
    spacing, since dn/di <= pi A / L). A block for columns a..b with n
    layers: start = (x_a - 2 r, -r), end = (x_b + 2 r, (2 n + 1) r)
    (denseMode 0 puts centres at start + 2r (1 + j), j < round(size/2r) - 1;
    z a +-4 r slab, as in dfsph_column.py). The script checks the particle
    count against sum(n_i).
  * Walls: UnitBox.obj as a wall (mapInvert), spanning
    x in [-OFFSET r, L + OFFSET r], y in [-OFFSET r, 3 h] (the project's
    domain is 3 h tall). dfsph_column.py found that particle centres 2.2 r
    from a volume-map wall start at rest density (OFFSET = 1.2 r from the
    lattice's edge, which is r from the outer centres); it moves its column
    off the walls by 1.2 r. Here the tank is moved out instead, so the
    liquid's lattice spans exactly [0, L] x [0, surface] as in the C++ scene,
    the walls sit where a lattice at rest density puts them, and the tank is
    symmetric about x = L / 2, the rest value of the centre of mass. The
    volume map has one cell per kernel support radius (4 r) in x and y and
    four cells in z, as in dfsph_column.py.
  * Inviscid by default (viscosityMethod 0; vorticityMethod 0 always: the
    bundled micropolar model is no part of water). --viscosity NU turns on
    SPlisHSPlasH's "Standard viscosity" with coefficient NU (water: 1e-6
    m^2/s); its boundary viscosity stays at its default 0, so the walls are
    free-slip and water's wall boundary layers, the main cause of a real
    tank's damping (zeta of a few thousandths), are not modelled.
  * Time step: CFL as in the bundled scene (cflMethod 1, cflFactor 1); the
    cap cflMaxTimeStepSize is min(5 ms, r * 1 s/m) (about 1 ms at the default
    spacing) and, if viscous, at most 0.03 h_k^2 / nu (h_k = 4 r), as in
    dfsph_column.py; the CFL minimum is min(0.1 ms, 0.1 * the cap).
    --max-dt overrides the cap. The waves move at ~0.1 m/s, so the cap sets
    the step. At that cap DFSPH's pressure solve takes ~60 iterations a
    step; a cap four times smaller (--spacing L/128, --max-dt 0.0005) took
    ~4, ran in the same wall time and moved the period by 0.1 % and zeta by
    0.0006, so the step does not set the figures.

Measured: after every time step (base.setTimeStepCB), the simulated time and
the liquid's centre of mass along x (the mean x of the particle centres; all
particles have the same mass), read as a numpy view of the "position"
field; the samples are at most one step apart (the line printed says the
largest gap). The first mode moves the centre of mass 2 A L / (pi^2 h) =
10.1 mm from L / 2 (to the left at the start; the script prints the
lattice's own start, which the whole layers round). measure() below is measure_oscillation() of
oscillation.cpp line for line: crossings of L / 2 interpolated linearly, each
half cycle's peak the largest |x - L/2| between crossings (the first before
the first crossing) refined by the parabola through it and its neighbours,
the measurement ended at the first peak below 0.1 of the first, the period
twice the mean time between successive crossings over the half cycles
measured, zeta = decay / sqrt(omega_d^2 + decay^2) with decay the negated
slope of a least-squares fit of ln |peak| over time.

--pulse runs the travelling pulse of liquid/analysis/travelling_wave.h
instead (`liquid_validate --only travelling`): a hump h/10 high and
sigma = h/2 wide against the left wall, exp(-x^2 / (2 sigma^2)), on still
water rounded to whole layers, released at rest. It crosses the tank and
back; the tank's modes 1 to 3 carry it. Each mode's amplitude
a_n = (2 / L) sum_p s^2 cos(n pi x_p / L) is sampled after every step and
measured as above about 0, its period against linear theory at the depth
the liquid settles to (its section over L).

Setup (once; or `compare_dfsph.py --install`):
    python3 -m venv /opt/dfsph-venv
    /opt/dfsph-venv/bin/pip install pysplishsplash==2.19.0

Run (the package needs libGLdispatch preloaded to import; DFSPH uses OpenMP,
OMP_NUM_THREADS caps its threads):
    OMP_NUM_THREADS=1 LD_PRELOAD=/lib/x86_64-linux-gnu/libGLdispatch.so.0 \\
        /opt/dfsph-venv/bin/python tools/dfsph/dfsph_sloshing.py \\
        [--cells 128 | --spacing S] [--viscosity 1e-6] [--seconds 5] \\
        [--amplitude 0.01 | --pulse] [--max-dt DT]

Last line printed (machine-readable):
    dfsph_sloshing particles=N cells=C spacing=S radius=R viscosity=V period_s=P
        theory_s=T period_err=E zeta=Z half_cycles=H wall_s=W init_s=I
        steps=K max_sample_gap_s=G max_dt=D
    with --pulse:
    dfsph_pulse particles=N cells=C spacing=S radius=R viscosity=V depth=H
        mode1_period_err=E mode1_zeta=Z mode1_half_cycles=K (modes 1 to 3)
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

LENGTH = 0.5      # L [m]
DEPTH = 0.1       # h, still depth [m]
AMPLITUDE = 0.01  # A [m], the project's (--amplitude changes it)
HEIGHT = 3.0 * DEPTH  # tank height, the project's domain [m]
# assets/scenes/rest_pool_2d.json, whose regime (particles per cell) the
# project's sloshing scene keeps: particle spacing and cell size [m].
REST_POOL_SPACING = 0.004273504273504274
REST_POOL_CELL = 0.5 / 64
OFFSET = 1.2      # wall distance from the lattice's edge, in particle radii
FLOOR = 0.1       # measure_oscillation()'s default floor
PULSE_HEIGHT = 0.1 * DEPTH      # travelling_pulse()'s hump [m]
PULSE_HALF_WIDTH = 0.5 * DEPTH  # its sigma [m]
PULSE_MODES = 3   # the modes liquid_validate --only travelling measures

def sloshing_period(length, depth, gravity, mode=1):
    """oscillation.cpp's tank_mode_period(): linear theory, omega^2 = g k tanh(k h), k = n pi / L."""
    k = mode * math.pi / length
    return 2.0 * math.pi / math.sqrt(gravity * k * math.tanh(k * depth))


def measure(times, values, rest, floor=FLOOR):
    """oscillation.cpp's measure_oscillation(): (period, zeta, half_cycles, peaks)."""
    nan = float("nan")
    n = min(len(times), len(values))
    crossings, crossing_after = [], []
    for i in range(1, n):
        a, b = values[i - 1] - rest, values[i] - rest
        if (a < 0.0 and b >= 0.0) or (a > 0.0 and b <= 0.0):
            crossings.append(times[i - 1] + (times[i] - times[i - 1]) * a / (a - b))
            crossing_after.append(i)
    if len(crossings) < 2:
        return nan, nan, 0, []
    t_peak, log_peak = [], []
    for c in range(len(crossing_after)):
        first = 0 if c == 0 else crossing_after[c - 1]
        end = crossing_after[c]
        best = first
        for i in range(first, end):
            if abs(values[i] - rest) > abs(values[best] - rest):
                best = i
        t, y = times[best], abs(values[best] - rest)
        if best > 0 and best + 1 < n:
            y0, y2 = abs(values[best - 1] - rest), abs(values[best + 1] - rest)
            curvature = y0 - 2.0 * y + y2
            if curvature < 0.0:
                shift = 0.5 * (y0 - y2) / curvature
                y -= 0.25 * (y0 - y2) * shift
                t += shift * 0.5 * (times[best + 1] - times[best - 1])
        if log_peak and y < floor * math.exp(log_peak[0]):
            break
        t_peak.append(t)
        log_peak.append(math.log(y))
    peaks = list(zip(t_peak, [math.exp(v) for v in log_peak]))
    half_cycles = len(t_peak) - 1
    if half_cycles < 1:
        return nan, nan, 0, peaks
    period = 2.0 * (crossings[half_cycles] - crossings[0]) / half_cycles
    if len(t_peak) < 2:
        return period, nan, half_cycles, peaks
    mt = sum(t_peak) / len(t_peak)
    my = sum(log_peak) / len(log_peak)
    stt = sum((t - mt) * (t - mt) for t in t_peak)
    sty = sum((t - mt) * (y - my) for t, y in zip(t_peak, log_peak))
    decay = -sty / stt
    omega_d = 2.0 * math.pi / period
    zeta = decay / math.sqrt(omega_d * omega_d + decay * decay)
    return period, zeta, half_cycles, peaks


def max_time_step(radius, viscosity, override):
    if override is not None:
        return override
    dt = min(BUNDLED_CONFIG["cflMaxTimeStepSize"], radius * 1.0)
    if viscosity:
        dt = min(dt, 0.03 * (4.0 * radius) ** 2 / viscosity)
    return dt


def mode_surface(amplitude):
    """sloshing_scene()'s surface: the first mode, eta = A cos(pi x / L)."""
    return lambda x: DEPTH + amplitude * math.cos(math.pi * x / LENGTH)


def pulse_surface(spacing, height):
    """travelling_pulse_scene()'s surface (liquid/analysis/travelling_wave.cpp):
    a hump height * exp(-x^2 / (2 sigma^2)), sigma = h / 2, against the left
    wall, on still water rounded to whole layers."""
    still = max(1.0, round(DEPTH / spacing)) * spacing
    sigma = PULSE_HALF_WIDTH
    return lambda x: still + height * math.exp(-0.5 * (x / sigma) ** 2)


def columns(spacing, surface):
    """tank_scene()'s columns: (centre x, layers) for each particle column,
    the whole number of layers nearest surface(centre)."""
    count = int(math.floor(LENGTH / spacing + 1e-4))
    out = []
    for i in range(count):
        centre = (i + 0.5) * spacing
        out.append((centre, int(max(1.0, round(surface(centre) / spacing)))))
    return out


def build_scene(out_dir, radius, surface, viscosity, seconds, max_dt):
    wall = OFFSET * radius
    tank = (LENGTH + 2.0 * wall, HEIGHT + wall)
    centre = (LENGTH / 2.0, (HEIGHT - wall) / 2.0)
    material = {
        "id": "Fluid",
        "density0": 1000,
        "viscosityMethod": 1 if viscosity else 0,
        "vorticityMethod": 0,
        "Standard viscosity": {"viscosity": viscosity or 0.0},
    }
    cols = columns(2.0 * radius, surface)
    # Runs of neighbouring columns with the same layer count, one block each.
    runs = []
    for x, n in cols:
        if runs and runs[-1][2] == n:
            runs[-1][1] = x
        else:
            runs.append([x, x, n])
    for a, b, n in runs:
        if b - a < radius or n < 2:
            sys.exit("a run of columns at x = %.4f is %d wide and %d high: a FluidBlock "
                     "needs two particles each way" % (a, round((b - a) / (2 * radius)) + 1, n))
    # denseMode 0: centres at start + 2r*(1 + j), j < round(size/2r) - 1.
    blocks = [{
        "denseMode": 0,
        "start": [a - 2.0 * radius, -radius, -4 * radius],
        "end": [b + 2.0 * radius, (2 * n + 1) * radius, 4 * radius],
        "translation": [0, 0, 0],
        "scale": [1, 1, 1],
    } for a, b, n in runs]
    tank_body, map_res = tank_wall(centre, tank, radius)
    scene = {
        "Configuration": configuration_2d(radius, max_dt, seconds),
        "Materials": [material],
        "RigidBodies": [tank_body],
        "FluidBlocks": blocks,
    }
    path = os.path.join(out_dir, "SloshingTank_2D.json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
    return path, map_res, cols, len(blocks)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    lattice = parser.add_mutually_exclusive_group()
    lattice.add_argument("--cells", type=int, default=128,
                         help="the project's lattice at this many cells along L: spacing "
                              "(L/cells) * 64/117 (default 128: L/234 = 2.137 mm)")
    lattice.add_argument("--spacing", type=float, default=None,
                         help="particle spacing 2r in m instead of --cells; L/spacing "
                              "should be a whole number")
    parser.add_argument("--viscosity", type=float, default=0.0,
                        help="'Standard viscosity' coefficient, m^2/s (default 0: "
                             "inviscid; water 1e-6)")
    parser.add_argument("--amplitude", type=float, default=AMPLITUDE,
                        help="the mode's amplitude A in m (default 0.01, the project's)")
    parser.add_argument("--pulse", action="store_true",
                        help="the travelling pulse instead of the first mode: a hump h/10 "
                             "high, sigma h/2 wide, against the left wall; measures "
                             "modes 1 to 3 as liquid_validate --only travelling does")
    parser.add_argument("--seconds", type=float, default=5.0,
                        help="simulated time (default 5, about 4.7 periods)")
    parser.add_argument("--max-dt", type=float, default=None,
                        help="cflMaxTimeStepSize (default: min(5 ms, r*1 s/m, "
                             "0.03 (4r)^2/nu if viscous))")
    args = parser.parse_args()

    if args.spacing is not None:
        spacing, cells_label = args.spacing, "-"
    else:
        spacing = LENGTH / args.cells * REST_POOL_SPACING / REST_POOL_CELL
        cells_label = str(args.cells)
    r = 0.5 * spacing
    theory = sloshing_period(LENGTH, DEPTH, G)
    rest = 0.5 * LENGTH
    visc_label = "%g" % args.viscosity if args.viscosity else "off"

    work_dir = tempfile.mkdtemp(prefix="dfsph_sloshing_")
    try:
        max_dt = max_time_step(r, args.viscosity, args.max_dt)
        surface = (pulse_surface(spacing, PULSE_HEIGHT) if args.pulse
                   else mode_surface(args.amplitude))
        scene_file, map_res, cols, n_blocks = build_scene(
            work_dir, r, surface, args.viscosity, args.seconds, max_dt)
        wall_init0 = time.perf_counter()
        run = Run(scene_file, work_dir, args.seconds)
        base, sim, tm, fluid, positions = run.base, run.sim, run.time, run.fluid, run.positions
        n = fluid.numActiveParticles()
        expected = sum(layers for _, layers in cols)
        if n != expected:
            sys.exit("the blocks gave %d particles, the columns %d" % (n, expected))

        def centre_x():
            return float(np.mean(positions()[:, 0], dtype=np.float64))

        # tank_mode_amplitude(): a_n = (2 / L) sum_p s^2 cos(k_n x_p).
        wavenumbers = np.pi * np.arange(1, PULSE_MODES + 1) / LENGTH

        def modes():
            x = positions()[:, 0].astype(np.float64)
            return 2.0 / LENGTH * spacing * spacing * np.cos(np.outer(wavenumbers, x)).sum(axis=1)

        p0 = positions()
        x0 = centre_x()
        print("particles=%d columns=%d blocks=%d spacing=%g radius=%g viscosity=%s max_dt=%.3g "
              "map_resolution=%s x=[%.5f, %.5f] y=[%.5f, %.5f] walls x=[%.5f, %.5f] "
              "floor y=%.5f method=%d (4 = DFSPH)"
              % (n, len(cols), n_blocks, spacing, sim.getParticleRadius(), visc_label, max_dt,
                 list(map_res), p0[:, 0].min(), p0[:, 0].max(), p0[:, 1].min(),
                 p0[:, 1].max(), -OFFSET * r, LENGTH + OFFSET * r, -OFFSET * r,
                 run.method()), flush=True)
        if not args.pulse:
            print("centre of mass x(0) - L/2 = %.3f mm (the mode: -2AL/(pi^2 h) = %.3f mm)"
                  % (1e3 * (x0 - rest), -1e3 * 2 * args.amplitude * LENGTH / (math.pi ** 2 * DEPTH)),
                  flush=True)

        sample = (lambda: (tm.getTime(), *modes())) if args.pulse else (lambda: (tm.getTime(), centre_x()))
        samples = [sample()]
        wall_marks = []
        first_density = []

        def on_step():
            samples.append(sample())
            wall_marks.append(time.perf_counter())
            if not first_density:
                rho = np.asarray(fluid.getFieldBuffer("density"))[:fluid.numActiveParticles()]
                p = positions()
                # Below the lowest surface by two spacings: next to a wall or
                # the floor (within two spacings), and the rest.
                deep = p[:, 1] < DEPTH - args.amplitude - 2 * spacing
                near = ((p[:, 0] < 2 * spacing) | (p[:, 0] > LENGTH - 2 * spacing)
                        | (p[:, 1] < 2 * spacing))
                first_density.append((float(np.mean(rho[deep & near])),
                                      float(np.mean(rho[deep & ~near]))))

        base.setTimeStepCB(on_step)
        base.runSimulation()
        wall_end = time.perf_counter()
        base.cleanup()
    finally:
        shutil.rmtree(work_dir, ignore_errors=True)

    if len(samples) < 3:
        sys.exit("fewer than two time steps ran; increase --seconds")
    t = [s[0] for s in samples]
    gap = float(np.max(np.diff(t)))
    # runSimulation() starts with the deferred boundary initialisation (the
    # volume map); the first step's callback marks its end.
    init_s = wall_marks[0] - wall_init0
    sim_wall = wall_end - wall_marks[0]
    if first_density:
        print("density after the first step, below the surface: within 2 spacings of "
              "the walls %.1f, elsewhere %.1f" % first_density[0])
    if args.pulse:
        # Linear theory at the depth the liquid settles to, its section over L, as
        # liquid_validate takes it.
        depth = spacing * spacing * n / LENGTH
        fields = []
        for mode in range(1, PULSE_MODES + 1):
            period, zeta, half_cycles, peaks = measure(t, [s[mode] for s in samples], 0.0)
            theory = sloshing_period(LENGTH, depth, G, mode)
            err = period / theory - 1.0
            print("mode %d: a(0) %.3f mm, period %.4f s, linear theory %.4f s, error %+.2f %%; "
                  "zeta %.4f over %d half cycles" % (mode, 1e3 * samples[0][mode], period, theory,
                                                     100 * err, zeta, half_cycles))
            fields.append("mode%d_period_err=%.4f mode%d_zeta=%.4f mode%d_half_cycles=%d"
                          % (mode, err, mode, zeta, mode, half_cycles))
        print("dfsph_pulse particles=%d cells=%s spacing=%g radius=%g viscosity=%s depth=%.5f %s "
              "wall_s=%.1f init_s=%.1f steps=%d max_sample_gap_s=%.2e max_dt=%.3g"
              % (n, cells_label, spacing, r, visc_label, depth, " ".join(fields), sim_wall, init_s,
                 len(samples) - 1, gap, max_dt))
        return
    x = [s[1] for s in samples]
    period, zeta, half_cycles, peaks = measure(t, x, rest)
    err = period / theory - 1.0
    print("t_end=%.3f steps=%d max_sample_gap=%.2e s; half-cycle peaks |x - L/2| (t s, mm):"
          % (t[-1], len(samples) - 1, gap))
    print("  " + ", ".join("%.3f %.3f" % (tp, 1e3 * yp) for tp, yp in peaks))
    print("period %.4f s, linear theory %.4f s, error %+.2f %%; zeta %.4f over %d half cycles"
          % (period, theory, 100 * err, zeta, half_cycles))
    print("dfsph_sloshing particles=%d cells=%s spacing=%g radius=%g viscosity=%s period_s=%.4f "
          "theory_s=%.4f period_err=%.4f zeta=%.4f half_cycles=%d wall_s=%.1f init_s=%.1f "
          "steps=%d max_sample_gap_s=%.2e max_dt=%.3g"
          % (n, cells_label, spacing, r, visc_label, period, theory, err, zeta, half_cycles,
             sim_wall, init_s, len(samples) - 1, gap, max_dt))


if __name__ == "__main__":
    main()
