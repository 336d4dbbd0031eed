// The solver's per-step inputs on the CPU: the wall-kernel table, the uniform block's fields and
// the specialization constants a scene's features give its shaders.
#include "liquid/specialization.h"
#include "liquid/uniforms.h"
#include "liquid/wall_coverage.h"
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
    scene.pressure_force = force;
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
  CHECK_THROWS_AS(make_uniforms(Scene{}, SimulationSetup{}, {}), std::invalid_argument);
}

TEST_CASE("the uniform block carries the setup's parameters and the step's inputs", "[uniforms]") {
  const Scene scene = scene_of("obstacles_2d.json");
  const SimulationSetup setup = make_setup(scene, {});
  StepInputs step;
  step.dt = 1e-4f;
  step.active_before = 10;
  step.active_after = 12;
  step.brushes = {ForceBrush{{0.1f, 0.2f, 0.0f}, 0.05f, {1.0f, 2.0f, 0.0f}}};
  const gpu::SolverUniforms u = make_uniforms(scene, setup, step);
  CHECK(u.domain == setup.domain);
  CHECK(u.cell_size == setup.cell_size);
  CHECK(u.grid_cells == setup.grid_cells);
  CHECK(u.particle_texture_width == setup.particle_texture.x);
  CHECK(u.dt == 1e-4f);
  CHECK(u.stiffness == setup.stiffness);
  CHECK(u.rest_density == setup.rest_density);
  CHECK(u.density_scale == setup.density_scale);
  CHECK(u.kernel_radius == setup.kernel_radius_cells);
  CHECK(u.pic_ratio == setup.pic_ratio);
  CHECK(u.wall_margin == setup.wall_margin);
  CHECK(u.obstacle_band == setup.obstacle_band);
  CHECK(u.active_before == 10);
  CHECK(u.active_after == 12);
  CHECK(u.brush_count == 1);
  CHECK(u.brushes[0].radius == 0.05f);
  CHECK(u.brushes[0].acceleration == glm::vec3(1.0f, 2.0f, 0.0f));
  // obstacles_2d: a sphere, a box and metaballs, at their scene poses when no pose is given.
  REQUIRE(scene.obstacles.size() == 3);
  CHECK(u.obstacles[0].center == scene.obstacles[0].center);
  CHECK(u.obstacles[0].sphere_radius == scene.obstacles[0].radius);
  CHECK(u.obstacles[1].box_half_extent == scene.obstacles[1].half_extent);
  CHECK(u.obstacles[2].metaball_threshold == scene.obstacles[2].threshold);
  CHECK(u.obstacles[2].first_ball == 0);
  CHECK(u.obstacles[2].ball_count == int(scene.obstacles[2].balls.size()));
  CHECK(u.balls[0] == glm::vec4(scene.obstacles[2].balls[0].center, scene.obstacles[2].balls[0].radius));
}

TEST_CASE("the shaders' specialization follows the scene's features", "[setup]") {
  // constant_id layout of shaders/liquid/common.glsl (tests/cpu/test_shaders.cpp checks the ids):
  // obstacle count, 8 kinds, shallow water, integer gamma, emitters, ground hills.
  namespace id = specialization_id;
  const std::vector<int32_t> dam = scene_specialization(scene_of("dam_break_2d.json"), setup_of("dam_break_2d.json"));
  CHECK(dam == std::vector<int32_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5, 0, 0});

  const std::vector<int32_t> obstacles = scene_specialization(scene_of("obstacles_2d.json"), setup_of("obstacles_2d.json"));
  REQUIRE(obstacles.size() == id::count);
  CHECK(obstacles[id::obstacle_count] == 3);
  CHECK(std::vector<int32_t>(obstacles.begin() + id::first_obstacle_kind, obstacles.begin() + id::first_obstacle_kind + 3) ==
        std::vector<int32_t>{0, 1, 2});  // sphere, box, metaballs

  const std::vector<int32_t> shallow = scene_specialization(scene_of("shallow_water.json"), setup_of("shallow_water.json"));
  CHECK(shallow[id::shallow_water] == 1);
  CHECK(shallow[id::integer_gamma] == 1);  // gamma = 1: P = g (h + b)
  CHECK(shallow[id::ground_hills] == 3);

  CHECK(scene_specialization(scene_of("paper_3d.json"), setup_of("paper_3d.json"))[id::has_emitters] == 1);  // the jet

  Scene fractional = load_scene(k_scene_dir / "dam_break_2d.json");
  fractional.gamma = 6.5f;
  CHECK(scene_specialization(fractional, make_setup(fractional, {}))[id::integer_gamma] == 0);  // pow() in the shader
}
