// The separable splat ("splat": "separable"): on the GPU, on every grid path, its grid is exactly
// the tensor-product kernel of liquid/physics/kernel.h summed over the particles and their mirror
// images across the walls (the deposit folds them in; the spread's taps are mirrored), and the
// velocity it carries is the particles'.
#include "liquid/node.h"
#include "liquid/physics/kernel.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

// The particle's coordinate (cells) and its mirror images across both walls of an axis of n cells.
std::array<double, 3> images_along(double g, int n) { return {g, -g, 2.0 * n - g}; }

// sum over particles and mirror images of prod_a profile(x_cell - x_p), in double precision.
std::vector<double> separable_weights(const liquid::SimulationSetup& s, const std::vector<glm::vec4>& positions) {
  const glm::ivec3 n = s.grid_cells;
  const double r = s.kernel_radius_cells;
  std::vector<double> w(size_t(n.x) * n.y * n.z, 0.0);
  for (const glm::vec4& p : positions) {
    const glm::dvec3 g = glm::dvec3(p) / double(s.cell_size);
    for (int z = 0; z < n.z; ++z)
      for (int y = 0; y < n.y; ++y)
        for (int x = 0; x < n.x; ++x) {
          double fx = 0.0, fy = 0.0, fz = 1.0;
          for (double i : images_along(g.x, n.x)) fx += liquid::separable_profile(x + 0.5 - i, r);
          for (double i : images_along(g.y, n.y)) fy += liquid::separable_profile(y + 0.5 - i, r);
          if (s.dimension == 3) {
            fz = 0.0;
            for (double i : images_along(g.z, n.z)) fz += liquid::separable_profile(z + 0.5 - i, r);
          }
          w[(size_t(z) * n.y + y) * n.x + x] += fx * fy * fz;
        }
  }
  return w;
}

// The splat tests' scene with the separable splat, particles allowed up to the walls.
liquid::Scene separable_scene(int dimension, glm::vec3 at) {
  liquid::Scene scene = test::single_particle_scene(dimension, at);
  scene.wall_margin_cells = 0.0f;
  scene.splat = liquid::SplatMode::Separable;
  return scene;
}

// Runs one step (its splat is of the initial particles) and compares the grid with the CPU's sum.
void check_separable_splat(liquid::LiquidNode& node, bool check_velocity) {
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  REQUIRE(setup.splat == liquid::SplatMode::Separable);
  const std::vector<double> expected = separable_weights(setup, setup.positions);
  test::run_steps(node, 1);  // its splat is of the initial particles
  const std::vector<glm::vec4> splat = node.read_splat();
  REQUIRE(splat.size() == expected.size());
  double total = 0.0, total_expected = 0.0, worst = 0.0, largest = 0.0;
  for (size_t i = 0; i < splat.size(); ++i) {
    total += splat[i].a;
    total_expected += expected[i];
    worst = std::max(worst, std::abs(double(splat[i].a) - expected[i]));
    largest = std::max(largest, expected[i]);
    if (check_velocity && splat[i].a > 1e-3f) {
      CHECK(splat[i].r / splat[i].a == Approx(0.5f).epsilon(1e-4));
      CHECK(splat[i].g / splat[i].a == Approx(-0.25f).epsilon(1e-4));
    }
  }
  INFO("total weight " << total << ", expected " << total_expected << ", worst cell error " << worst);
  REQUIRE(total_expected > 0.0);
  CHECK(std::abs(total - total_expected) < 1e-4 * total_expected);
  CHECK(worst < 1e-4 * std::max(1.0, largest));
  REQUIRE_NO_VALIDATION_MESSAGES_ON(node.context());
}

}  // namespace

TEST_CASE("separable splat of one 2D particle is the product kernel, mirrored at the walls", "[gpu][liquid][splat]") {
  // Inside, a third of a cell from a wall (its mirror image adds there), and in a corner.
  for (const glm::vec3 at : {glm::vec3(0.1313f, 0.1777f, 0.0f), glm::vec3(0.0067f, 0.1511f, 0.0f),
                             glm::vec3(0.3147f, 0.0031f, 0.0f)}) {
    INFO("particle at " << at.x << ", " << at.y);
    liquid::LiquidNode node(test::gpu(), separable_scene(2, at));
    REQUIRE(node.active_particles() == 1);
    check_separable_splat(node, true);
  }
}

// On every 3D path; in the atlas the corner particle's deposit must stay in its own tile.
TEMPLATE_TEST_CASE("separable splat of one 3D particle is the product kernel, mirrored at the walls",
                   "[gpu][liquid][splat][paths]", test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  for (const glm::vec3 at : {glm::vec3(0.1313f, 0.1777f, 0.1522f), glm::vec3(0.3131f, 0.2953f, 0.0057f)}) {
    INFO("particle at " << at.x << ", " << at.y << ", " << at.z);
    liquid::LiquidNode node(test::gpu_for(TestType::path), separable_scene(3, at), test::options_for(TestType::path));
    REQUIRE(node.active_particles() == 1);
    check_separable_splat(node, true);
  }
}

TEST_CASE("separable splat of a 2D block against a wall sums every particle's kernel", "[gpu][liquid][splat]") {
  liquid::Scene scene = separable_scene(2, {});
  scene.fluid_blocks = {{{0.0f, 0.03f, 0.0f}, {0.17f, 0.13f, 0.0f}, {}}};
  liquid::LiquidNode node(test::gpu(), scene);
  REQUIRE(node.active_particles() > 1000);
  check_separable_splat(node, false);
}

TEMPLATE_TEST_CASE("separable splat of a 3D block in a corner sums every particle's kernel",
                   "[gpu][liquid][splat][paths]", test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  liquid::Scene scene = separable_scene(3, {});
  scene.particle_spacing = 0.012f;
  scene.fluid_blocks = {{{0.0f, 0.0f, 0.07f}, {0.17f, 0.13f, 0.32f}, {}}};
  liquid::LiquidNode node(test::gpu_for(TestType::path), scene, test::options_for(TestType::path));
  REQUIRE(node.active_particles() > 1000);
  check_separable_splat(node, false);
}
