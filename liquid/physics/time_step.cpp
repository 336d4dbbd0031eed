#include "liquid/physics/time_step.h"

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {

// The long steps' CFL numbers were measured with a kernel of 3 cells.
double kernel_scale(double kernel_radius_cells) { return kernel_radius_cells / 3.0; }

double regime_acoustic_cfl(bool long_steps, double kernel_radius_cells) {
  return long_steps ? k_acoustic_cfl_smoothed * kernel_scale(kernel_radius_cells) : k_acoustic_cfl_chapter;
}

// The speed of sound at rest density, sqrt(k gamma), m/s.
double rest_sound(double stiffness, double gamma) { return std::sqrt(std::max(stiffness, 0.0) * gamma); }

// sqrt(2 |g| L): a fall from rest across a side of length L, m/s.
double fall_speed(double gravity, double longest) { return std::sqrt(2.0 * gravity * longest); }

// The velocity CFL a default step keeps to when there is no sound to bound it (AdaptiveTimeStep's).
constexpr double k_default_velocity_cfl = 0.4;

}  // namespace

double regime_acoustic_cfl(const SimulationSetup& setup) {
  return regime_acoustic_cfl(setup.long_steps, setup.kernel_radius_cells);
}

double stable_acoustic_cfl(const SimulationSetup& setup) {
  return setup.long_steps ? k_acoustic_cfl_smoothed_stable * kernel_scale(setup.kernel_radius_cells)
                          : k_max_acoustic_cfl_chapter;
}

double speed_of_sound(const SimulationSetup& setup, double density_ratio) {
  const double ratio = std::max(density_ratio, 1.0);  // below rest density the clamp leaves P = 0
  return std::sqrt(double(setup.stiffness) * setup.gamma * std::pow(ratio, double(setup.gamma)));
}

double fall_speed(const SimulationSetup& setup) {
  return fall_speed(glm::length(setup.gravity), longest_side(setup.domain, setup.dimension));
}

double scene_time_step(const Scene& scene) {
  if (scene.time_step > 0.0f) return scene.time_step;
  const double h = scene_cell_size(scene);
  const PressureLaw law = pressure_law(scene);
  const double sound = rest_sound(law.stiffness, law.gamma);
  if (sound > 0.0)
    return std::min(regime_acoustic_cfl(long_step_regime(scene), scene.kernel_radius_cells) * h / sound, k_max_time_step);
  const double fall = fall_speed(glm::length(scene.gravity), longest_side(scene.domain, scene.dimension));
  return fall > 0.0 ? std::min(k_default_velocity_cfl * h / fall, k_max_time_step) : k_max_time_step;
}

double largest_stable_time_step(const SimulationSetup& setup) {
  const double signal = speed_of_sound(setup, 1.0) + fall_speed(setup);
  return signal > 0.0 ? stable_acoustic_cfl(setup) * setup.cell_size / signal : double(k_max_time_step);
}

RuntimeParameterRange runtime_parameter_range(const SimulationSetup& setup, double time_step, float stiffness,
                                              glm::vec3 gravity) {
  const double longest = longest_side(setup.domain, setup.dimension);
  const double k = std::max(double(stiffness), 0.0), g = glm::length(gravity);
  // The fastest signal the step may carry: sound plus the flow, within the stable acoustic CFL.
  const double signal = stable_acoustic_cfl(setup) * setup.cell_size / time_step;
  const double sound = rest_sound(k, setup.gamma), fall = fall_speed(g, longest);
  RuntimeParameterRange r;
  const double left_for_fall = std::max(signal - sound, 0.0);
  r.max_gravity = float(std::min(k_max_hydrostatic_ratio * k, 0.5 * left_for_fall * left_for_fall) / longest);
  const double left_for_sound = std::max(signal - fall, 0.0);
  r.max_stiffness = float(std::clamp(left_for_sound * left_for_sound / setup.gamma, 1.0, 500.0));
  r.min_stiffness = float(std::min(g * longest / k_max_hydrostatic_ratio, double(r.max_stiffness)));
  return r;
}

double cfl_time_step(const SimulationSetup& setup, const AdaptiveTimeStep& cfl, const Diagnostics& d, double largest) {
  const double h = setup.cell_size;
  const double speed = std::isfinite(d.max_speed) ? std::max(double(d.max_speed), 0.0) : 0.0;
  const double ratio = std::isfinite(d.max_density_ratio) ? double(d.max_density_ratio) : 1.0;
  double dt = largest;
  const double acoustic = speed_of_sound(setup, ratio) + speed;
  if (acoustic > 0.0) dt = std::min(dt, cfl.acoustic_cfl * h / acoustic);
  if (speed > 0.0) dt = std::min(dt, cfl.velocity_cfl * h / speed);
  return dt;
}

}  // namespace liquid
