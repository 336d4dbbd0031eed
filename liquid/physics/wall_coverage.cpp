#include "liquid/physics/wall_coverage.h"

#include "liquid/physics/kernel.h"

#include <algorithm>
#include <cmath>

namespace liquid {
namespace {

constexpr int k_converged_samples = 4096;

}  // namespace

double kernel_mass_beyond_wall(int dimension, double radius_cells, double distance_cells, int samples) {
  if (distance_cells >= radius_cells) return 0.0;
  const double exponent = dimension == 3 ? 4.0 : 3.5;
  double beyond = 0.0, total = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double z = -radius_cells + (i + 0.5) * (2.0 * radius_cells / samples);
    const double profile = std::pow(std::max(1.0 - z * z / (radius_cells * radius_cells), 0.0), exponent);
    total += profile;
    if (z > distance_cells) beyond += profile;
  }
  return beyond / total;
}

double lattice_mass_beyond_wall(int dimension, double spacing_cells, double radius_cells, double distance_cells) {
  if (distance_cells >= radius_cells) return 0.0;
  if (radius_cells / spacing_cells > k_max_summed_lattice_ratio)
    return kernel_mass_beyond_wall(dimension, radius_cells, distance_cells, k_converged_samples);
  const int reach = int(std::ceil(radius_cells / spacing_cells)) + 1;
  const int normal_reach = int(std::ceil((distance_cells + radius_cells) / spacing_cells)) + 1;
  const int offsets_z = dimension == 3 ? k_lattice_offsets_per_axis : 1;
  const int kz_reach = dimension == 3 ? reach : 0;
  double inside = 0.0, total = 0.0;
  for (int oz = 0; oz < offsets_z; ++oz)
    for (int oy = 0; oy < k_lattice_offsets_per_axis; ++oy)
      for (int kz = -kz_reach; kz <= kz_reach; ++kz)
        for (int ky = -reach; ky <= reach; ++ky) {
          const double dy = (ky + (oy + 0.5) / k_lattice_offsets_per_axis) * spacing_cells;
          const double dz = dimension == 3 ? (kz + (oz + 0.5) / k_lattice_offsets_per_axis) * spacing_cells : 0.0;
          // Layers at (i + 0.5) s from the wall: i >= 0 inside, i < 0 the mirror image.
          for (int i = -normal_reach; i < normal_reach; ++i) {
            const double dx = (i + 0.5) * spacing_cells - distance_cells;
            const double w = kernel_weight(dx * dx + dy * dy + dz * dz, radius_cells);
            total += w;
            if (i >= 0) inside += w;
          }
        }
  return total > 0.0 ? 1.0 - inside / total : 0.0;
}

std::vector<float> wall_share_beyond(const Scene& scene, double spacing_cells, int size) {
  std::vector<float> table(size_t(size), 0.0f);
  if (scene.splat == SplatMode::Separable) return table;
  const double r = scene.kernel_radius_cells;
  for (int k = 0; k < size; ++k)
    table[size_t(k)] = float(uses_splat_adjoint_pressure(scene)
                                 ? lattice_mass_beyond_wall(scene.dimension, spacing_cells, r, k + 0.5)
                                 : kernel_mass_beyond_wall(scene.dimension, r, k + 0.5, k_wall_samples_chapter));
  return table;
}

std::vector<float> body_share_beyond(const Scene& scene, double spacing_cells, int size) {
  std::vector<float> table(size_t(size), 0.0f);
  for (int k = 0; k < size; ++k)
    table[size_t(k)] = float(lattice_mass_beyond_wall(scene.dimension, spacing_cells, scene.kernel_radius_cells, k + 0.5));
  return table;
}

}  // namespace liquid
