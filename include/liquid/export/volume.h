// The grids a frame exports, read back from a node: rho/rho0 and the grid velocity per cell, with
// the placement that maps a cell to metres, and with whitewater the foam's number density splatted
// onto the same cells. Used for OpenVDB volumes and per-particle density.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace engine::vk {
class Context;
}

namespace liquid {

class LiquidNode;
struct WhitewaterParticle;

struct VolumeFrame {
  glm::ivec3 cells{1};                // cells per axis (z = 1 in 2D)
  float cell_size = 0.0f;             // m; cell (i, j, k) spans [i, i + 1] * cell_size from the origin
  glm::vec3 origin{0.0f};             // m, the domain's corner
  std::vector<float> density;         // rho/rho0, x fastest, then y, then z
  std::vector<glm::vec4> velocity;    // m/s in xyz; w = 1 where the cell holds liquid
  // Foam particles per m^3 (foam_number_density()), the same order; empty for a scene without
  // whitewater, which then has no foam grid.
  std::vector<float> foam;
  size_t index(int x, int y, int z) const { return size_t(x) + size_t(cells.x) * (size_t(y) + size_t(cells.y) * z); }
};

// Blocking read of the node's density and grid-velocity images (call with no frame in flight).
VolumeFrame read_volume(engine::vk::Context& context, LiquidNode& node);

// rho/rho0 at each position: trilinear (bilinear in 2D) between cell centres, clamped at the
// outermost centres, as the solver's particle pass samples its grids.
std::vector<float> sample_density(const VolumeFrame& volume, const std::vector<glm::vec4>& positions);
float density_at(const VolumeFrame& volume, const glm::vec3& position);  // the same at one position

// The grid velocity at each position, m/s: the same stencil over the cells that hold liquid only,
// weights renormalised (a surface point has air cells in its stencil, whose velocity is zero and
// would slow it down); zero where no cell of the stencil holds liquid.
std::vector<glm::vec3> sample_velocity(const VolumeFrame& volume, const std::vector<glm::vec3>& positions);

// The foam's number density per cell, particles per m^3: each foam particle (WhitewaterKind::Foam;
// spray and bubbles are left out) spread over the cells of the stencil above with its weights,
// which sum to 1, and divided by the cell's volume (cell_size^3, in 2D too: the grid one cell
// deep). Summed over the cells and multiplied by cell_size^3 it is the foam particles' count.
std::vector<float> foam_number_density(const VolumeFrame& volume, const std::vector<WhitewaterParticle>& particles);

}  // namespace liquid
