// The separable splat's kernel on the CPU (liquid/physics/kernel.h): the bilinear deposit followed
// by one pass of taps per axis is the taps' piecewise-linear interpolant per axis, the setup's
// calibrations use that kernel, and the walls need no coverage table.
#include "liquid/physics/kernel.h"
#include "liquid/physics/setup.h"
#include "liquid/physics/wall_coverage.h"
#include "liquid/scene.h"
#include "shaders/liquid/shared.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace liquid;

namespace {

// The GPU's two stages on a 1D row of n cells (cell c's centre at c + 0.5), for a particle at g
// (cells): the deposit of the position clamped to the outermost centres, then the taps with
// mirrored cells beyond the walls (deposit.vert, separable_blur.frag).
std::vector<double> deposit_then_spread(double g, int n, double r) {
  std::vector<double> deposit(size_t(n), 0.0), out(size_t(n), 0.0);
  const double x = std::clamp(g, 0.5, n - 0.5) - 0.5;  // in centre coordinates
  const int i = int(std::floor(x));
  deposit[size_t(i)] += 1.0 - (x - i);
  if (i + 1 < n) deposit[size_t(i + 1)] += x - i;
  const auto mirror = [n](int k) { return k < 0 ? -1 - k : (k >= n ? 2 * n - 1 - k : k); };
  const int reach = separable_reach(r);
  for (int c = 0; c < n; ++c)
    for (int j = -reach; j <= reach; ++j) out[size_t(c)] += kernel_weight(double(j) * j, r) * deposit[size_t(mirror(c + j))];
  return out;
}

}  // namespace

TEST_CASE("the separable kernel's profile is the linear interpolant of its taps", "[setup][splat]") {
  for (double r : {1.5, 3.0, 4.25, 8.0}) {
    INFO("r = " << r);
    const int reach = separable_reach(r);
    CHECK(reach == int(std::ceil(r)) - 1);
    for (int j = -reach; j <= reach; ++j) CHECK(separable_profile(j, r) == Approx(kernel_weight(double(j) * j, r)));
    CHECK(separable_profile(reach + 1, r) == 0.0);
    CHECK(separable_profile(reach + 1.5, r) == 0.0);
    CHECK(separable_profile(0.25, r) == Approx(0.75 + 0.25 * kernel_weight(1.0, r)));
    CHECK(splat_kernel_support(SplatMode::Separable, r) == reach + 1);
    // The product of the axes' profiles; the radial kernel for the point sprites.
    CHECK(splat_kernel_weight(SplatMode::Separable, 0.3, -1.2, 0.7, r) ==
          Approx(separable_profile(0.3, r) * separable_profile(1.2, r) * separable_profile(0.7, r)));
    CHECK(splat_kernel_weight(SplatMode::PointSprite, 0.3, -1.2, 0.7, r) == Approx(kernel_weight(0.09 + 1.44 + 0.49, r)));
  }
}

TEST_CASE("the separable deposit and spread give the profile, with the particle's mirror image at a wall",
          "[setup][splat]") {
  const int n = 16;
  const double r = 3.0;
  // In the middle, half a cell from a wall, at a wall, and a hair inside the far one.
  for (double g : {7.37, 0.5, 0.2, 0.0, 15.93, 3.81}) {
    INFO("particle at " << g << " cells");
    const std::vector<double> spread = deposit_then_spread(g, n, r);
    for (int c = 0; c < n; ++c) {
      // The particle and its mirror images across both walls (at 0 and n).
      const double centre = c + 0.5;
      const double expected = separable_profile(centre - g, r) + separable_profile(centre + g, r) +
                              separable_profile(centre - (2.0 * n - g), r);
      CHECK(spread[size_t(c)] == Approx(expected).margin(1e-12));
    }
  }
}

TEST_CASE("the separable kernel's integral and the setup's calibrations use it", "[setup][splat]") {
  for (double r : {1.5, 3.0, 5.5}) {
    double taps = 0.0;
    for (int j = -separable_reach(r); j <= separable_reach(r); ++j) taps += kernel_weight(double(j) * j, r);
    // A fine Riemann sum of the profile is the taps' sum (each tap's hat has unit area).
    double sum = 0.0;
    const double step = 1e-3;
    for (double t = -r - 1.0 + step / 2; t < r + 1.0; t += step) sum += separable_profile(t, r) * step;
    CHECK(sum == Approx(taps).epsilon(1e-6));
    CHECK(splat_kernel_integral_cells(SplatMode::Separable, 2, r) == Approx(taps * taps));
    CHECK(splat_kernel_integral_cells(SplatMode::Separable, 3, r) == Approx(taps * taps * taps));
    CHECK(splat_kernel_integral_cells(SplatMode::PointSprite, 3, r) == Approx(kernel_integral_cells(3, r)));
  }
  // A uniform lattice of the liquid's density reads it: the automatic rest density is within a
  // fraction of a percent of the density (the lattice sum against the integral), by either kernel.
  for (const SplatMode mode : {SplatMode::PointSprite, SplatMode::Separable}) {
    Scene scene = test_scenes::scene_of("dam_break_2d.json");
    scene.splat = mode;
    const SimulationSetup setup = make_setup(scene, {});
    CHECK(setup.splat == mode);
    CHECK(setup.rest_density == Approx(scene.density).epsilon(0.01));
    CHECK(setup.density_scale == Approx(setup.particle_mass / (std::pow(setup.cell_size, 2) *
                                                              splat_kernel_integral_cells(mode, 2, scene.kernel_radius_cells))));
  }
}

TEST_CASE("the separable splat needs no wall coverage table", "[setup][splat][uniforms]") {
  for (const auto force : {PressureForce::Chapter, PressureForce::SplatAdjoint}) {
    Scene scene = test_scenes::scene_of("rest_pool_2d.json");
    scene.projection_iterations = 0;  // the chapter's pressure has no projection
    scene.pressure_force = force;
    scene.time_step = 0.0f;
    scene.splat = SplatMode::Separable;
    const SimulationSetup setup = make_setup(scene, {});
    REQUIRE(setup.wall_share_beyond.size() == size_t(gpu::k_wall_table_size));
    for (float share : setup.wall_share_beyond) CHECK(share == 0.0f);
    scene.splat = SplatMode::PointSprite;
    CHECK(make_setup(scene, {}).wall_share_beyond[0] > 0.1f);
  }
}

TEST_CASE("the scene key splat picks the point sprites or the separable splat", "[scene][splat]") {
  const std::string head = R"({"dimension": 2, "domain": [1, 1], "particle_spacing": 0.02,
    "fluid_blocks": [{"min": [0.1, 0.1], "max": [0.3, 0.3]}])";
  CHECK(parse_scene(head + "}", "plain.json").splat == SplatMode::Separable);  // the default
  CHECK(parse_scene(head + R"(, "splat": "point_sprite"})", "p.json").splat == SplatMode::PointSprite);
  CHECK(parse_scene(head + R"(, "splat": "separable"})", "s.json").splat == SplatMode::Separable);
  CHECK_THROWS_WITH(parse_scene(head + R"(, "splat": "gaussian"})", "bad.json"),
                    Catch::Contains("bad.json: splat") && Catch::Contains("separable"));
  CHECK_THROWS_WITH(parse_scene(head + R"(, "splat": 1})", "bad.json"), Catch::Contains("splat"));
}
