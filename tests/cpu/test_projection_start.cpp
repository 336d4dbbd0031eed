// The pressure projection's first guess (liquid/solver/projection_start.h): still water's pressure
// over the initial particles, in the layout's texels.
#include "liquid/solver/projection_start.h"
#include "liquid/solver/pressure.h"

#include <catch2/catch.hpp>

using namespace liquid;

namespace {

// A pool `depth_cells` deep on the floor (or against the ceiling with gravity up) of cells of 1 cm,
// two particles per cell side.
SimulationSetup pool(int dimension, glm::ivec3 cells, int depth_cells, glm::vec3 gravity) {
  SimulationSetup s;
  s.dimension = dimension;
  s.grid_cells = cells;
  s.cell_size = 0.01f;
  s.particle_spacing = 0.005f;
  s.gravity = gravity;
  const bool up = gravity.y > 0.0f;
  const int nz = dimension == 3 ? 2 * cells.z : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < 2 * depth_cells; ++j)
      for (int i = 0; i < 2 * cells.x; ++i) {
        const float y = (j + 0.5f) * s.particle_spacing;
        s.positions.emplace_back((i + 0.5f) * s.particle_spacing, up ? cells.y * s.cell_size - y : y,
                                 dimension == 3 ? (k + 0.5f) * s.particle_spacing : 0.0f, 1.0f);
      }
  return s;
}

float p_at(const std::vector<float>& values, const GridLayout& layout, int x, int y, int z) {
  return values[layout.texel_index(x, y, z) * k_projection_pressure_channels];
}

}  // namespace

TEST_CASE("the projection starts from still water's pressure over the initial particles", "[projection]") {
  const double g = 9.81, h = 0.01;
  SECTION("2D, gravity down") {
    const SimulationSetup s = pool(2, {8, 10, 1}, 6, {0.0f, -9.81f, 0.0f});
    const GridLayout layout(2, s.grid_cells, GridPath::VertexLayer);
    const std::vector<float> v = hydrostatic_projection_start(s, layout);
    REQUIRE(v.size() == 8 * 10 * k_projection_pressure_channels);
    for (int x = 0; x < 8; ++x)
      for (int y = 0; y < 10; ++y) {
        INFO("cell " << x << ", " << y);
        // The cell's centre lies 6 h - (y + 0.5) h below the surface; no liquid above the pool.
        CHECK(p_at(v, layout, x, y, 0) == Approx(y < 6 ? g * (6 - y - 0.5) * h : 0.0).margin(1e-6));
        CHECK(v[layout.texel_index(x, y, 0) * k_projection_pressure_channels + 1] == 0.0f);  // psi
      }
  }
  SECTION("3D in the atlas, gravity up: the liquid hangs from the ceiling") {
    const SimulationSetup s = pool(3, {4, 6, 5}, 2, {0.0f, 9.81f, 0.0f});
    const GridLayout layout(3, s.grid_cells, GridPath::Atlas);
    const std::vector<float> v = hydrostatic_projection_start(s, layout);
    const engine::vk::ImageDesc desc = layout.image_desc(k_projection_pressure_format, 0);
    REQUIRE(v.size() == size_t(desc.width) * desc.height * k_projection_pressure_channels);
    for (int z = 0; z < 5; ++z)
      for (int y = 0; y < 6; ++y) {
        INFO("cell 2, " << y << ", " << z);
        const int depth = y - 3;  // cells 4 and 5 hold the liquid, "above" it is below them
        CHECK(p_at(v, layout, 2, y, z) == Approx(depth >= 1 ? g * (depth - 0.5) * h : 0.0).margin(1e-6));
      }
  }
  SECTION("no single axis of gravity: no guess") {
    const SimulationSetup s = pool(2, {8, 10, 1}, 6, {3.0f, -9.81f, 0.0f});
    const std::vector<float> v = hydrostatic_projection_start(s, GridLayout(2, s.grid_cells, GridPath::VertexLayer));
    for (float x : v) CHECK(x == 0.0f);
  }
}
