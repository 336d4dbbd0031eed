#include "liquid/analysis/travelling_wave.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace liquid {

TravellingPulse travelling_pulse(int dimension, int cells_along) {
  TravellingPulse pulse;
  pulse.tank = sloshing_tank(dimension, cells_along);
  pulse.height = 0.1 * pulse.tank.depth;
  pulse.half_width = 0.5 * pulse.tank.depth;
  return pulse;
}

double pulse_surface(const TravellingPulse& pulse, double x) {
  const double s = x / pulse.half_width;
  return pulse.tank.depth + pulse.height * std::exp(-0.5 * s * s);
}

Scene travelling_pulse_scene(const Scene& physics, const TravellingPulse& pulse) {
  // The still depth a whole number of layers, so that rounding each column to its nearest layer
  // rounds the hump alone, both ways, rather than widening it where the still level rounds down.
  const double still = tank_still_depth(physics, pulse.tank);
  return tank_scene(physics, pulse.tank, [&](double x) { return pulse_surface(pulse, x) - pulse.tank.depth + still; });
}

double pulse_mode_amplitude(const TravellingPulse& pulse, int mode) {
  // Simpson's rule on a grid far finer than the hump and the mode.
  const double length = pulse.tank.length, k = mode * std::numbers::pi / length;
  const int intervals = 4096;
  const double dx = length / intervals;
  double sum = 0.0;
  for (int i = 0; i <= intervals; ++i) {
    const double x = i * dx, weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * (pulse_surface(pulse, x) - pulse.tank.depth) * std::cos(k * x);
  }
  return 2.0 / length * sum * dx / 3.0;
}

double tank_mode_amplitude(const ParticleSnapshot& particles, int mode, double length, double area_per_particle) {
  const double k = mode * std::numbers::pi / length;
  double sum = 0.0;
  for (const glm::vec4& p : particles.positions)
    if (std::isfinite(p.x)) sum += std::cos(k * p.x);
  return 2.0 / length * area_per_particle * sum;
}

}  // namespace liquid
