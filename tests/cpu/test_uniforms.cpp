// The solver's per-step inputs on the CPU: the uniform block's fields and the specialization
// constants a scene's features give its shaders (the wall table: test_wall_coverage.cpp).
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace liquid;
using namespace test_scenes;

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
  // obstacle count, 8 kinds, shallow water, integer gamma, emitters, ground hills, walls continued.
  namespace id = specialization_id;
  const std::vector<int32_t> dam = scene_specialization(scene_of("dam_break_2d.json"), setup_of("dam_break_2d.json"));
  CHECK(dam == std::vector<int32_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5, 0, 0, 1});  // the separable splat's walls

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
  // Point sprites read the walls' coverage from the table.
  CHECK(scene_specialization(scene_of("paper_3d.json"), setup_of("paper_3d.json"))[id::walls_continued] == 0);

  Scene fractional = load_scene(k_scene_dir / "dam_break_2d.json");
  fractional.gamma = 6.5f;
  CHECK(scene_specialization(fractional, make_setup(fractional, {}))[id::integer_gamma] == 0);  // pow() in the shader
}
