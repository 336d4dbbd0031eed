#include "liquid/solver/projection_start.h"

#include "liquid/solver/pressure.h"

#include <algorithm>
#include <cmath>

namespace liquid {

std::vector<float> hydrostatic_projection_start(const SimulationSetup& setup, const GridLayout& layout) {
  const engine::vk::ImageDesc desc = layout.image_desc(k_projection_pressure_format, 0);
  std::vector<float> values(size_t(desc.width) * desc.height * desc.depth_or_layers * k_projection_pressure_channels, 0.0f);
  const int axis = single_gravity_axis(setup.dimension, setup.gravity);
  if (axis < 0) return values;
  const glm::ivec3 n = setup.grid_cells;
  const double h = setup.cell_size;
  const auto cell_of = [&](const glm::vec4& p) {
    glm::ivec3 c(0);
    for (int a = 0; a < setup.dimension; ++a) c[a] = std::clamp(int(std::floor(p[a] / h)), 0, n[a] - 1);
    return c;
  };
  const auto linear = [&](glm::ivec3 c) { return size_t(c.x) + size_t(n.x) * (size_t(c.y) + size_t(n.y) * c.z); };
  std::vector<int> count(size_t(n.x) * n.y * n.z, 0);
  for (const glm::vec4& p : setup.positions) ++count[linear(cell_of(p))];
  // A particle's share of a column's height: its volume over the column's cross-section.
  const double height_per_particle = std::pow(double(setup.particle_spacing), setup.dimension) / std::pow(h, setup.dimension - 1);
  const double g = std::abs(double(setup.gravity[axis]));
  const bool down = setup.gravity[axis] < 0.0f;  // "above" is towards larger indices when gravity points down
  glm::ivec3 column_cells = n;
  column_cells[axis] = 1;
  for (int k = 0; k < column_cells.z; ++k)
    for (int j = 0; j < column_cells.y; ++j)
      for (int i = 0; i < column_cells.x; ++i) {
        double above = 0.0;  // the liquid's height above the current cell, m
        for (int step = 0; step < n[axis]; ++step) {
          glm::ivec3 c(i, j, k);
          c[axis] = down ? n[axis] - 1 - step : step;
          const double own = count[linear(c)] * height_per_particle;
          if (count[linear(c)] > 0)
            values[layout.texel_index(c.x, c.y, c.z) * k_projection_pressure_channels] = float(g * (above + 0.5 * own));
          above += own;
        }
      }
  return values;
}

}  // namespace liquid
