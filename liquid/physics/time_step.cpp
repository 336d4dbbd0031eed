#include "liquid/physics/time_step.h"

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {

// The long steps' CFL numbers were measured with a kernel of 3 cells.
double kernel_scale(const SimulationSetup& setup) { return setup.kernel_radius_cells / 3.0; }

}  // namespace

double regime_acoustic_cfl(const SimulationSetup& setup) {
  return setup.long_steps ? k_acoustic_cfl_smoothed * kernel_scale(setup) : k_acoustic_cfl_chapter;
}

double stable_acoustic_cfl(const SimulationSetup& setup) {
  return setup.long_steps ? k_acoustic_cfl_smoothed_stable * kernel_scale(setup) : k_max_acoustic_cfl_chapter;
}

double speed_of_sound(const SimulationSetup& setup, double density_ratio) {
  const double ratio = std::max(density_ratio, 1.0);  // below rest density the clamp leaves P = 0
  return std::sqrt(double(setup.stiffness) * setup.gamma * std::pow(ratio, double(setup.gamma)));
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
