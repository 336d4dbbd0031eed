// The wall-coverage table on the CPU: the kernel's mass beyond a wall that the splat misses, and
// the uniform block that carries it to the grid pass, by the scene's pressure force.
#include "liquid/physics/wall_coverage.h"
#include "liquid/solver/uniforms.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace liquid;
using namespace test_scenes;

TEST_CASE("the wall table holds the kernel's mass beyond a plane", "[setup][uniforms]") {
  for (int dimension : {2, 3}) {
    for (double r : {1.5, 3.0, 8.0}) {
      // A plane through the centre cuts the symmetric kernel in half; none is beyond r.
      CHECK(kernel_mass_beyond_wall(dimension, r, 0.0, k_wall_samples_chapter) == Approx(0.5).margin(1e-3));
      CHECK(kernel_mass_beyond_wall(dimension, r, r, k_wall_samples_chapter) == 0.0);
      CHECK(lattice_mass_beyond_wall(dimension, 0.4, r, r) == 0.0);
      double previous = 0.5, previous_lattice = 0.5;
      for (double a = 0.5; a < r; a += 1.0) {
        const double beyond = kernel_mass_beyond_wall(dimension, r, a, k_wall_samples_chapter);
        const double lattice = lattice_mass_beyond_wall(dimension, 0.4, r, a);
        CHECK(beyond <= previous);
        CHECK(beyond >= 0.0);
        CHECK(lattice <= previous_lattice);
        CHECK(lattice >= 0.0);
        previous = beyond;
        previous_lattice = lattice;
      }
    }
  }
  // 2D, r = 3, half a cell away: the share of (1 - z^2/9)^3.5 beyond z = 0.5 is 0.3123; the
  // chapter mode's 16-interval rule gives 0.3565 (see wall_coverage.h). The lattice's own share
  // tends to the integral as the spacing falls (within 0.1 % at 0.2 cells), and at 0.4 cells is within
  // 0.2 % of it.
  CHECK(kernel_mass_beyond_wall(2, 3.0, 0.5, 4096) == Approx(0.3123).margin(1e-4));
  CHECK(kernel_mass_beyond_wall(2, 3.0, 0.5, k_wall_samples_chapter) == Approx(0.3565).margin(1e-3));
  CHECK(lattice_mass_beyond_wall(2, 0.2, 3.0, 0.5) == Approx(0.3123).margin(1e-3));
  CHECK(lattice_mass_beyond_wall(3, 0.2, 3.0, 1.5) == Approx(kernel_mass_beyond_wall(3, 3.0, 1.5, 4096)).margin(1e-3));
  CHECK(lattice_mass_beyond_wall(2, 0.4, 3.0, 0.5) == Approx(0.3123).margin(2e-3));
}

TEST_CASE("the uniform block carries the setup's wall table, by the scene's pressure force", "[setup][uniforms]") {
  for (const auto force : {PressureForce::Chapter, PressureForce::SplatAdjoint}) {
    Scene scene = scene_of("rest_pool_2d.json");
    scene.projection_iterations = 0;  // the chapter's pressure has no projection
    scene.pressure_force = force;
    scene.splat = SplatMode::PointSprite;  // the separable splat needs no table (test_splat_kernel.cpp)
    scene.time_step = 0.0f;  // each regime's own step (the chapter's refuses the long one)
    const SimulationSetup setup = make_setup(scene, {});
    const double spacing_cells = setup.particle_spacing / setup.cell_size;
    const gpu::SolverUniforms u = make_uniforms(scene, setup, {});
    REQUIRE(setup.wall_share_beyond.size() == size_t(gpu::k_wall_table_size));
    for (int k = 0; k < gpu::k_wall_table_size; ++k) {
      const double expected = force == PressureForce::Chapter
                                  ? kernel_mass_beyond_wall(2, 3.0, k + 0.5, k_wall_samples_chapter)
                                  : lattice_mass_beyond_wall(2, spacing_cells, 3.0, k + 0.5);
      CHECK(u.wall_kernel_beyond[k / 4][k % 4] == Approx(expected));
    }
    CHECK(u.wall_kernel_beyond[0][3] == 0.0f);  // r = 3: nothing beyond 3.5 cells
  }
  // A setup built by hand without the table would silently turn the wall correction off.
  CHECK_THROWS_AS(make_uniforms(Scene{}, SimulationSetup{}, {}), std::logic_error);
}
