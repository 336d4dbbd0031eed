#include "liquid/export/volume.h"

#include "engine/graph/transfer.h"
#include "liquid/node.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace liquid {

VolumeFrame read_volume(engine::vk::Context& context, LiquidNode& node) {
  const SimulationSetup& s = node.setup();
  VolumeFrame v;
  v.cells = s.grid_cells;
  v.cell_size = s.cell_size;
  v.density = node.read_density_ratio();
  const size_t cells = size_t(v.cells.x) * v.cells.y * v.cells.z;
  const std::vector<std::byte> bytes = engine::graph::download_image(context, node.state().grid_velocity);
  if (v.density.size() != cells || bytes.size() != cells * sizeof(glm::vec4))
    throw std::logic_error("read_volume: grid readback of unexpected size");
  v.velocity.resize(cells);
  std::memcpy(v.velocity.data(), bytes.data(), bytes.size());
  return v;
}

std::vector<float> sample_density(const VolumeFrame& volume, const std::vector<glm::vec4>& positions) {
  const glm::ivec3 n = volume.cells;
  const bool flat = n.z == 1;
  std::vector<float> out;
  out.reserve(positions.size());
  for (const glm::vec4& p : positions) {
    // Cell centres sit at (i + 0.5) h: g is the position in centre coordinates.
    glm::vec3 g = (glm::vec3(p) - volume.origin) / volume.cell_size - 0.5f;
    g = glm::clamp(g, glm::vec3(0.0f), glm::vec3(n - 1));
    if (!std::isfinite(g.x + g.y + g.z)) g = glm::vec3(0.0f);
    const glm::ivec3 base = glm::min(glm::ivec3(glm::floor(g)), glm::max(n - 2, glm::ivec3(0)));
    const glm::vec3 f = g - glm::vec3(base);
    float value = 0.0f;
    for (int corner = 0; corner < (flat ? 4 : 8); ++corner) {
      const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const glm::ivec3 c = glm::min(base + o, n - 1);
      const glm::vec3 t = glm::mix(1.0f - f, f, glm::vec3(o));
      const float weight = t.x * t.y * (flat ? 1.0f : t.z);
      value += weight * volume.density[volume.index(c.x, c.y, c.z)];
    }
    out.push_back(value);
  }
  return out;
}

}  // namespace liquid
