// Standing waves, the motion games and shots are made of: a tank's first sloshing mode against
// linear theory, and the period and damping ratio of a measured oscillation. Pure CPU code, used by
// the validation tool (tools/liquid_validate/main.cpp) and the physics tests.
#pragma once

#include "liquid/scene.h"
#include "liquid/types.h"

#include <functional>
#include <span>

namespace liquid {

// A rectangular tank of length L and still depth h whose surface starts as the first mode,
// eta(x) = A cos(pi x / L): the liquid rises at x = 0 and falls at x = L. 3D: the tank is `width`
// deep along z and the mode uniform across it.
struct SloshingTank {
  int dimension = 2;
  double length = 0.5;      // L, m
  double depth = 0.1;       // h, m
  double amplitude = 0.01;  // A, m
  double width = 0.05;      // 3D only: along z, m
  int cells_along = 128;    // grid cells along L
};

// The tank of `dimension` on `cells_along` cells along L, in 3D six cells across (the mode is
// uniform along z): the one liquid_validate and the tests run.
SloshingTank sloshing_tank(int dimension, int cells_along);

// Mode n's period by linear theory: omega^2 = g k tanh(k h), k = n pi / L (s). Its surface is
// eta(x) = a cos(n pi x / L).
double tank_mode_period(double length, double depth, double gravity, int mode);

// The first mode's period: tank_mode_period(..., 1).
double sloshing_period(double length, double depth, double gravity);

// `physics` (its regime: stiffness, gamma, pressure, splat, PIC blend; its blocks and obstacles are
// dropped) filling `tank`: one fluid block a particle column wide per column of the lattice, each
// as tall as the mode's surface over its centre, on a grid of tank.cells_along cells along L, with
// headroom of twice the depth, the particle spacing half a cell and the steps scaled to the cell
// (scene_at_spacing()).
Scene sloshing_scene(const Scene& physics, const SloshingTank& tank);

// The same with the liquid's surface at rest as `surface_at(x)` (m above the floor; the tank's
// amplitude unused): sloshing_scene() is this with the first mode's surface.
Scene tank_scene(const Scene& physics, const SloshingTank& tank, const std::function<double(double)>& surface_at);

// The tank's still depth rounded to whole layers of the particles `physics` gives it (m).
double tank_still_depth(const Scene& physics, const SloshingTank& tank);

// The section of the liquid each particle of `scene` stands for at rest (m^2): spacing^2, and in 3D
// its volume over the tank's width. In 3D the blocks fill whole spacings across (tank_scene()
// snaps the spacing to the width) but their columns, spread over L, may be a hair wider than a
// spacing, so the blocks' extent would overstate it.
double particle_section(const Scene& scene);

// The depth the liquid of `particles` particles settles to over the tank's floor (m): their
// sections over L. Linear theory is taken at this depth.
double settled_depth(const Scene& scene, size_t particles);

// The liquid's centre of mass along x, m: the first mode moves it 2 A L / (pi^2 h) from L / 2, so
// its oscillation is the mode's.
double centre_of_mass_x(const ParticleSnapshot& particles);

// Of samples (t, y) of a decaying oscillation about `rest`: the period (twice the mean time between
// successive crossings of `rest`), the damping ratio zeta from a least-squares fit of ln |peak| over
// time (each peak the extreme between two crossings, the first the one before the first crossing),
// and how many half cycles between crossings were measured: those
// up to the first whose peak is below `floor` times the first one's (past it, a strongly damped
// motion's crossings are its noise). No half cycle measured: period and zeta are NaN.
struct Oscillation {
  double period = 0.0;
  double damping_ratio = 0.0;
  int half_cycles = 0;
};
Oscillation measure_oscillation(std::span<const double> times, std::span<const double> values, double rest,
                               double floor = 0.1);

}  // namespace liquid
