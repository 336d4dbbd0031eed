#include "liquid/analysis/validation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace liquid {

std::span<const ExperimentPoint> martin_moyce_front() {
  // n^2 = 2 (height 2a), a = 2.25 in: front Z at the times T it passed each mark.
  static constexpr std::array<ExperimentPoint, 15> k_points{{{0.41, 1.11},
                                                             {0.84, 1.22},
                                                             {1.19, 1.44},
                                                             {1.43, 1.67},
                                                             {1.63, 1.89},
                                                             {1.83, 2.11},
                                                             {1.98, 2.33},
                                                             {2.20, 2.56},
                                                             {2.32, 2.78},
                                                             {2.51, 3.00},
                                                             {2.65, 3.22},
                                                             {2.83, 3.44},
                                                             {2.98, 3.67},
                                                             {3.11, 3.89},
                                                             {3.33, 4.11}}};
  return k_points;
}

double surge_front(const ParticleSnapshot& particles) {
  double front = 0.0;
  for (const glm::vec4& p : particles.positions)
    if (std::isfinite(p.x)) front = std::max(front, double(p.x));
  return front;
}

namespace {

size_t cell_index(const SimulationSetup& s, int x, int y, int z) {
  return (size_t(z) * size_t(s.grid_cells.y) + size_t(y)) * size_t(s.grid_cells.x) + size_t(x);
}

}  // namespace

double occupied_volume(const std::vector<float>& density_ratio, const SimulationSetup& setup, float iso) {
  size_t cells = 0;
  for (float r : density_ratio)
    if (r >= iso) ++cells;
  return double(cells) * std::pow(double(setup.cell_size), setup.dimension);
}

std::vector<double> surface_heights(const std::vector<float>& density_ratio, const SimulationSetup& setup, float iso) {
  const glm::ivec3 n = setup.grid_cells;
  const double h = setup.cell_size;
  std::vector<double> heights;
  if (density_ratio.size() < size_t(n.x) * n.y * n.z) return heights;
  for (int z = 0; z < n.z; ++z)
    for (int x = 0; x < n.x; ++x) {
      double height = -1.0;
      for (int y = n.y - 1; y >= 0; --y) {
        const double r = density_ratio[cell_index(setup, x, y, z)];
        if (r < iso) continue;
        // Between this cell's centre (r >= iso) and the one above (below iso, or the top wall).
        const double above = y + 1 < n.y ? density_ratio[cell_index(setup, x, y + 1, z)] : 0.0;
        const double f = r > above ? (r - iso) / (r - above) : 0.0;
        height = (y + 0.5 + std::clamp(f, 0.0, 1.0)) * h;
        break;
      }
      heights.push_back(height);
    }
  return heights;
}

double volume_under_surface(const std::vector<double>& heights, const SimulationSetup& setup) {
  double sum = 0.0;
  for (double h : heights) sum += std::max(h, 0.0);
  return sum * std::pow(double(setup.cell_size), setup.dimension - 1);
}

double particles_rest_volume(const SimulationSetup& setup) {
  return double(setup.initial_particles) * double(setup.particle_mass) / double(setup.rest_density);
}

FrontError compare_front(std::span<const double> T, std::span<const double> Z, double t_min, double t_max) {
  FrontError error;
  if (T.size() < 2 || T.size() != Z.size()) return error;
  double sum = 0.0;
  for (const ExperimentPoint& e : martin_moyce_front()) {
    if (e.T < t_min || e.T > t_max || e.T < T.front() || e.T > T.back()) continue;
    const size_t i = size_t(std::upper_bound(T.begin(), T.end(), e.T) - T.begin());
    const size_t hi = std::min(i, T.size() - 1), lo = hi - 1;
    const double f = T[hi] > T[lo] ? (e.T - T[lo]) / (T[hi] - T[lo]) : 0.0;
    const double z = Z[lo] + f * (Z[hi] - Z[lo]);
    const double relative = std::abs(z - e.Z) / e.Z;
    sum += relative;
    error.max = std::max(error.max, relative);
    ++error.points;
    error.model.push_back(z);
  }
  if (error.points > 0) error.mean = sum / error.points;
  return error;
}

ReleasedFront compare_front_released(std::span<const double> T, std::span<const double> Z, double max_delay) {
  ReleasedFront result;
  result.at_once = compare_front(T, Z);
  result.released = result.at_once;
  std::vector<double> later(T.begin(), T.end());
  const int steps = int(std::floor(max_delay / k_release_delay_step + 1e-9));
  for (int k = 1; k <= steps; ++k) {
    const double delay = k * k_release_delay_step;
    for (size_t i = 0; i < later.size(); ++i) later[i] = T[i] + delay;
    const FrontError e = compare_front(later, Z);
    // A delay that leaves experimental points uncovered measures less, so it cannot win.
    if (e.points >= result.released.points && e.mean < result.released.mean) {
      result.released = e;
      result.delay = delay;
    }
  }
  return result;
}

Scene scene_at_spacing(const Scene& base, double spacing) {
  Scene s = base;
  const double scale = spacing / base.particle_spacing;
  s.particle_spacing = float(spacing);
  if (base.grid_resolution) s.grid_resolution = int(std::lround(*base.grid_resolution / scale));
  s.time_step = float(base.time_step * scale);
  if (base.pic_ratio_reference_step) s.pic_ratio_reference_step = float(*base.pic_ratio_reference_step * scale);
  s.substeps = std::max(1, int(std::lround(base.substeps / scale)));
  return s;
}

double max_gain_in_window(std::span<const double> times, std::span<const double> energies, double t_from,
                          double window) {
  double gain = 0.0;
  for (size_t i = 0; i < times.size() && i < energies.size(); ++i) {
    if (times[i] < t_from) continue;
    for (size_t j = i + 1; j < times.size() && j < energies.size() && times[j] <= times[i] + window + 1e-9; ++j)
      gain = std::max(gain, energies[j] - energies[i]);
  }
  return gain;
}

}  // namespace liquid
