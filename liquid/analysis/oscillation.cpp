#include "liquid/analysis/oscillation.h"

#include "liquid/analysis/validation.h"
#include "liquid/physics/setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace liquid {

double tank_mode_period(double length, double depth, double gravity, int mode) {
  const double k = mode * std::numbers::pi / length;
  return 2.0 * std::numbers::pi / std::sqrt(gravity * k * std::tanh(k * depth));
}

double sloshing_period(double length, double depth, double gravity) {
  return tank_mode_period(length, depth, gravity, 1);
}

SloshingTank sloshing_tank(int dimension, int cells_along) {
  SloshingTank tank;
  tank.dimension = dimension;
  tank.cells_along = cells_along;
  tank.width = 6.0 * tank.length / cells_along;
  return tank;
}

Scene sloshing_scene(const Scene& physics, const SloshingTank& tank) {
  return tank_scene(physics, tank, [&](double x) {
    return tank.depth + tank.amplitude * std::cos(std::numbers::pi * x / tank.length);
  });
}

Scene tank_scene(const Scene& physics, const SloshingTank& tank, const std::function<double(double)>& surface_at) {
  Scene base = physics;
  base.fluid_blocks.clear();
  base.emitters.clear();
  base.obstacles.clear();
  base.dimension = tank.dimension;
  // The base's particles per cell, kept: its regime was tuned at that ratio.
  const double base_cell = double(std::max({physics.domain.x, physics.domain.y,
                                            physics.dimension == 3 ? physics.domain.z : 0.0f})) /
                           double(physics.grid_resolution.value_or(1));
  const double cell = tank.length / tank.cells_along;
  // Without a grid in the base, the default grid's spacings per cell, as make_setup() would choose.
  double spacing = physics.grid_resolution ? cell * physics.particle_spacing / base_cell
                                           : cell / k_default_spacings_per_cell;
  // 3D: the nearest spacing that fills the width with whole spacings. Ten spacings of the regime's
  // in the six cells across left 0.97 of one empty, and the liquid, spreading over it, started 9 %
  // below rest density: the surface came down for as long as the run.
  if (tank.dimension == 3) spacing = tank.width / std::max(1.0, std::round(tank.width / spacing));
  Scene s = scene_at_spacing(base, spacing);
  s.grid_resolution = tank.cells_along;
  s.domain = glm::vec3(float(tank.length), float(3.0 * tank.depth), tank.dimension == 3 ? float(tank.width) : 0.0f);
  s.gravity = glm::vec3(0.0f, -glm::length(physics.gravity), 0.0f);
  s.camera.reset();
  // As many columns as whole spacings fit, spread over L, each a spacing wide at the centre of its
  // share of L: no strip of the tank starts empty, and the lattice stays mirror-symmetric.
  const int columns = int(std::floor(tank.length / spacing + 1e-4));
  const double column = tank.length / columns;
  for (int i = 0; i < columns; ++i) {
    const double centre = (i + 0.5) * column, x0 = centre - 0.5 * spacing;
    const double surface = surface_at(centre);
    // A whole number of layers, the one nearest the surface.
    const double top = std::max(1.0, std::round(surface / spacing)) * spacing;
    FluidBlock block;
    block.min = glm::vec3(float(x0), 0.0f, 0.0f);
    block.max = glm::vec3(float(x0 + spacing), float(top), tank.dimension == 3 ? float(tank.width) : 0.0f);
    s.fluid_blocks.push_back(block);
  }
  return s;
}

double tank_still_depth(const Scene& physics, const SloshingTank& tank) {
  const double spacing = tank_scene(physics, tank, [&](double) { return tank.depth; }).particle_spacing;
  return std::max(1.0, std::round(tank.depth / spacing)) * spacing;
}

double particle_section(const Scene& scene) {
  const double s = scene.particle_spacing;
  return scene.dimension == 3 ? s * s * s / double(scene.domain.z) : s * s;
}

double settled_depth(const Scene& scene, size_t particles) {
  return double(particles) * particle_section(scene) / double(scene.domain.x);
}

double centre_of_mass_x(const ParticleSnapshot& particles) {
  double sum = 0.0;
  size_t n = 0;
  for (const glm::vec4& p : particles.positions)
    if (std::isfinite(p.x)) sum += p.x, ++n;
  return n ? sum / double(n) : std::numeric_limits<double>::quiet_NaN();
}

Oscillation measure_oscillation(std::span<const double> times, std::span<const double> values, double rest,
                               double floor) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const size_t n = std::min(times.size(), values.size());
  std::vector<double> crossings;  // times the value crosses `rest`
  std::vector<size_t> crossing_after;  // the first sample past each
  for (size_t i = 1; i < n; ++i) {
    const double a = values[i - 1] - rest, b = values[i] - rest;
    if ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)) {
      crossings.push_back(times[i - 1] + (times[i] - times[i - 1]) * a / (a - b));
      crossing_after.push_back(i);
    }
  }
  if (crossings.size() < 2) return {nan, nan, 0};
  // Each half cycle's peak: its largest |value - rest|, refined by the parabola through it and its
  // neighbours. Then ln |peak| = c - zeta omega_n t.
  // The samples before the first crossing count as a half cycle too (a motion released at rest
  // starts at its peak).
  std::vector<double> t_peak, log_peak;
  for (size_t c = 0; c < crossing_after.size(); ++c) {
    const size_t first = c == 0 ? 0 : crossing_after[c - 1], end = crossing_after[c];
    size_t best = first;
    for (size_t i = first; i < end; ++i)
      if (std::abs(values[i] - rest) > std::abs(values[best] - rest)) best = i;
    double t = times[best], y = std::abs(values[best] - rest);
    if (best > 0 && best + 1 < n) {
      const double y0 = std::abs(values[best - 1] - rest), y2 = std::abs(values[best + 1] - rest);
      const double curvature = y0 - 2.0 * y + y2;
      if (curvature < 0.0) {
        const double shift = 0.5 * (y0 - y2) / curvature;  // in samples, within [-0.5, 0.5]
        y -= 0.25 * (y0 - y2) * shift;
        t += shift * 0.5 * (times[best + 1] - times[best - 1]);
      }
    }
    // A motion damped below `floor` of its first peak is noise and drift: it ends the measurement.
    if (!log_peak.empty() && y < floor * std::exp(log_peak.front())) break;
    t_peak.push_back(t);
    log_peak.push_back(std::log(y));
  }
  // The half cycles between crossings whose peaks were measured (the first peak is before them).
  Oscillation o;
  o.half_cycles = int(t_peak.size()) - 1;
  if (o.half_cycles < 1) return {nan, nan, 0};
  o.period = 2.0 * (crossings[size_t(o.half_cycles)] - crossings.front()) / double(o.half_cycles);
  if (t_peak.size() < 2) return {o.period, nan, o.half_cycles};
  double mt = 0.0, my = 0.0;
  for (size_t i = 0; i < t_peak.size(); ++i) mt += t_peak[i], my += log_peak[i];
  mt /= double(t_peak.size());
  my /= double(t_peak.size());
  double stt = 0.0, sty = 0.0;
  for (size_t i = 0; i < t_peak.size(); ++i) stt += (t_peak[i] - mt) * (t_peak[i] - mt), sty += (t_peak[i] - mt) * (log_peak[i] - my);
  const double decay = -sty / stt;  // zeta omega_n, 1/s
  const double omega_d = 2.0 * std::numbers::pi / o.period;
  o.damping_ratio = decay / std::sqrt(omega_d * omega_d + decay * decay);
  return o;
}

}  // namespace liquid
