#include "liquid/analysis/still_water.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace liquid {

double particle_surface_level(const ParticleSnapshot& particles, double length, double spacing) {
  // The columns tile the middle 80 % exactly: a column cut by its edge would be a sliver that the
  // top layer, drifting sideways by a fraction of a spacing, can leave empty down to the floor.
  const double from = 0.1 * length, width = 0.8 * length;
  const int columns = std::max(1, int(width / (2.0 * spacing)));
  std::vector<double> top(size_t(columns), -1.0);
  for (const glm::vec4& p : particles.positions) {
    if (!(p.x > from && p.x < from + width) || !std::isfinite(p.y)) continue;
    const size_t c = size_t(std::min(columns - 1, int((p.x - from) / width * columns)));
    top[c] = std::max(top[c], double(p.y));
  }
  double sum = 0.0;
  int counted = 0;
  for (double t : top)
    if (t > 0.0) sum += t, ++counted;
  return counted ? sum / counted + 0.5 * spacing : std::numeric_limits<double>::quiet_NaN();
}

DensityProfile density_profile(const std::vector<float>& density_ratio, const SimulationSetup& setup, double surface) {
  const glm::ivec3 n = setup.grid_cells;
  const double h = setup.cell_size, reach = setup.kernel_radius_cells * h;
  DensityProfile profile;
  if (density_ratio.size() < size_t(n.x) * n.y * n.z) return profile;
  const int x_lo = int(0.1 * n.x), x_hi = std::max(x_lo + 1, int(std::ceil(0.9 * n.x)));
  double st = 0.0, sr = 0.0, stt = 0.0, str = 0.0;
  for (int y = 0; y < n.y; ++y) {
    const double centre = (y + 0.5) * h;
    if (centre <= reach || centre >= surface - reach) continue;
    double sum = 0.0;
    int cells = 0;
    for (int z = 0; z < n.z; ++z)
      for (int x = x_lo; x < x_hi; ++x)
        sum += density_ratio[(size_t(z) * size_t(n.y) + size_t(y)) * size_t(n.x) + size_t(x)], ++cells;
    const double depth = surface - centre, ratio = sum / cells;
    st += depth, sr += ratio, stt += depth * depth, str += depth * ratio;
    ++profile.rows;
  }
  if (profile.rows < 2) return {};
  const double rows = profile.rows, mean_ratio = sr / rows;
  profile.slope = (str - st * sr / rows) / (stt - st * st / rows);
  const double g = std::abs(double(setup.gravity.y));
  profile.hydrostatic =
      g / (double(setup.stiffness) * setup.gamma * std::pow(mean_ratio, double(setup.gamma) - 1.0));
  return profile;
}

}  // namespace liquid
