// Travelling waves: a pulse that crosses a tank, bounces off the far wall and comes back. A hump of
// water against the left wall released at rest sends a pulse of half its height across the tank
// (its mirror image in the wall sends the other half the same way). In a closed tank that pulse is
// the sum of the tank's standing modes, each started at rest,
//   eta(x, t) = sum_n a_n cos(n pi x / L) cos(omega_n t),  omega_n^2 = g k_n tanh(k_n h), k_n = n pi / L,
// so the measurement follows the first modes of that sum, each by its amplitude a_n(t) projected
// from the particles: its period against linear theory and its damping ratio say how fast the
// solver carries waves of those lengths and how fast it damps them. Pure CPU code, used by the
// validation tool (tools/liquid_validate/main.cpp) and the tests.
#pragma once

#include "liquid/analysis/oscillation.h"
#include "liquid/scene.h"
#include "liquid/types.h"

namespace liquid {

// The tank (its amplitude unused) and the hump at its left wall, eta(x) = height exp(-x^2 / (2 sigma^2)).
struct TravellingPulse {
  SloshingTank tank;
  double height = 0.0;      // m
  double half_width = 0.0;  // sigma, m
};

// The validation's pulse on `cells_along` cells along L: sloshing_tank()'s tank (L = 0.5 m,
// h = 0.1 m; 3D six cells across), a hump 1 cm high (h / 10) and sigma = h / 2 wide, which puts
// comparable amplitude into modes 1 to 3 (a_n falls as exp(-(k_n sigma)^2 / 2)).
TravellingPulse travelling_pulse(int dimension, int cells_along);

// The hump's surface at rest: h + eta(x).
double pulse_surface(const TravellingPulse& pulse, double x);

// `physics`'s regime filling the pulse's tank up to its hump (tank_scene()), the still depth rounded
// to whole layers of particles.
Scene travelling_pulse_scene(const Scene& physics, const TravellingPulse& pulse);

// a_n at t = 0 by the cosine series of the hump's smooth surface, (2 / L) int_0^L eta cos(k_n x) dx (m).
double pulse_mode_amplitude(const TravellingPulse& pulse, int mode);

// a_n of the particles' surface, n >= 1: (2 / L) int eta cos(k_n x) dx, which is
// (2 / L) sum_p A_p cos(k_n x_p) since the liquid below the still level adds nothing to it, each
// particle standing for `area_per_particle` of the liquid's section at rest (particle_section()) (m).
double tank_mode_amplitude(const ParticleSnapshot& particles, int mode, double length, double area_per_particle);

}  // namespace liquid
