#include "liquid/export/volume.h"

#include "engine/graph/transfer.h"
#include "liquid/node.h"
#include "liquid/solver/node_view.h"
#include "liquid/types.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace liquid {

// The node reads through its own context (the parameter stays for hosts that call this).
VolumeFrame read_volume(engine::vk::Context& /*context*/, LiquidNode& node) {
  const SimulationSetup& s = node_setup(node);
  VolumeFrame v;
  v.cells = s.grid_cells;
  v.cell_size = s.cell_size;
  // Both in x-fastest order on every 3D path (the node converts an atlas).
  v.density = node.read_density_ratio();
  v.velocity = node.read_grid_velocity();
  const size_t cells = size_t(v.cells.x) * v.cells.y * v.cells.z;
  if (v.density.size() != cells || v.velocity.size() != cells)
    throw std::logic_error("read_volume: grid readback of unexpected size");
  return v;
}

namespace {

// The trilinear (bilinear in 2D) stencil between cell centres at `position`, clamped at the
// outermost centres, as the solver's particle pass samples its grids: calls visit(cell, weight).
template <class Visit>
void for_each_stencil_cell(const VolumeFrame& volume, const glm::vec3& position, Visit visit) {
  const glm::ivec3 n = volume.cells;
  const bool flat = n.z == 1;
  // Cell centres sit at (i + 0.5) h: g is the position in centre coordinates.
  glm::vec3 g = (position - volume.origin) / volume.cell_size - 0.5f;
  g = glm::clamp(g, glm::vec3(0.0f), glm::vec3(n - 1));
  if (!std::isfinite(g.x + g.y + g.z)) g = glm::vec3(0.0f);
  const glm::ivec3 base = glm::min(glm::ivec3(glm::floor(g)), glm::max(n - 2, glm::ivec3(0)));
  const glm::vec3 f = g - glm::vec3(base);
  for (int corner = 0; corner < (flat ? 4 : 8); ++corner) {
    const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    const glm::ivec3 c = glm::min(base + o, n - 1);
    const glm::vec3 t = glm::mix(1.0f - f, f, glm::vec3(o));
    visit(volume.index(c.x, c.y, c.z), t.x * t.y * (flat ? 1.0f : t.z));
  }
}

}  // namespace

float density_at(const VolumeFrame& volume, const glm::vec3& position) {
  float value = 0.0f;
  for_each_stencil_cell(volume, position, [&](size_t cell, float weight) { value += weight * volume.density[cell]; });
  return value;
}

std::vector<float> sample_density(const VolumeFrame& volume, const std::vector<glm::vec4>& positions) {
  std::vector<float> out;
  out.reserve(positions.size());
  for (const glm::vec4& p : positions) out.push_back(density_at(volume, glm::vec3(p)));
  return out;
}

std::vector<glm::vec3> sample_velocity(const VolumeFrame& volume, const std::vector<glm::vec3>& positions) {
  std::vector<glm::vec3> out;
  out.reserve(positions.size());
  for (const glm::vec3& p : positions) {
    glm::vec3 sum(0.0f);
    float weights = 0.0f;
    for_each_stencil_cell(volume, p, [&](size_t cell, float weight) {
      const glm::vec4& v = volume.velocity[cell];
      if (v.w < 0.5f) return;  // air: its velocity is no one's
      sum += weight * glm::vec3(v);
      weights += weight;
    });
    out.push_back(weights > 0.0f ? sum / weights : glm::vec3(0.0f));
  }
  return out;
}

std::vector<float> foam_number_density(const VolumeFrame& volume, const std::vector<WhitewaterParticle>& particles) {
  std::vector<float> foam(size_t(volume.cells.x) * volume.cells.y * volume.cells.z, 0.0f);
  const float inverse_cell_volume = 1.0f / (volume.cell_size * volume.cell_size * volume.cell_size);
  for (const WhitewaterParticle& p : particles)
    if (p.kind == WhitewaterKind::Foam)
      for_each_stencil_cell(volume, p.position, [&](size_t cell, float weight) { foam[cell] += weight * inverse_cell_volume; });
  return foam;
}

}  // namespace liquid
