// Host resources of a long run: stepping and rendering must not grow the process's memory.
// Lavapipe used to allocate about 3 MB more per 3D solver step (a 16-frame demo ended near 8 GB)
// until the solver's shaders were specialized for the scene's features
// (shaders/liquid/common.glsl), about 2.7 MB per raymarched frame until the raymarch's loop
// bounds were constants, and about 12 KB per diagnose() until command buffers were recycled
// (docs/memory.md); these keep it so.
#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/memory.h"

#include <catch2/catch.hpp>

namespace {

// small_3d with every feature the shaders specialize for: a sphere, a box, metaballs, an emitter.
liquid::Scene busy_small_3d() {
  liquid::Scene scene = test::shipped_scene("small_3d");
  liquid::Obstacle sphere;
  sphere.shape = liquid::ObstacleShape::Sphere;
  sphere.center = {0.3f, 0.05f, 0.12f};
  sphere.radius = 0.04f;
  liquid::Obstacle box;
  box.shape = liquid::ObstacleShape::Box;
  box.center = {0.4f, 0.05f, 0.12f};
  box.half_extent = {0.03f, 0.03f, 0.03f};
  liquid::Obstacle blob;
  blob.shape = liquid::ObstacleShape::Metaballs;
  blob.threshold = 0.5f;
  blob.balls = {{{0.3f, 0.15f, 0.12f}, 0.04f}, {{0.33f, 0.15f, 0.12f}, 0.04f}};
  scene.obstacles = {sphere, box, blob};
  liquid::Emitter jet;
  jet.position = {0.05f, 0.22f, 0.12f};
  jet.velocity = {1.0f, 0.0f, 0.0f};
  jet.radius = 0.02f;
  jet.capacity = 2000;
  scene.emitters = {jet};
  return scene;
}

// How much the resident set grows (MiB) over `count` calls of `frame` after `warm_up` uncounted ones.
template <class Frame>
double resident_growth(int warm_up, int count, Frame frame) {
  double before = 0.0;
  for (int i = 0; i < warm_up + count; ++i) {
    if (i == warm_up) before = test::resident_mib();
    frame();
  }
  return test::resident_mib() - before;
}

// The resident set grew by less than `limit` MiB over the run (`over` says what it did).
void check_growth(double growth, const char* over, double limit) {
  INFO("resident set grew by " << growth << " MiB over " << over);
  CHECK(growth < limit);
}

}  // namespace

TEST_CASE("a long 3D run with obstacles, an emitter and a force brush does not grow host memory", "[gpu][liquid][resources]") {
  SKIP_UNDER_ADDRESS_SANITIZER();
  const liquid::Scene scene = busy_small_3d();
  liquid::LiquidNode node(test::gpu(), scene);
  node.set_brushes({{.position = {0.1f, 0.1f, 0.12f}, .radius = 0.08f, .acceleration = {2.0f, 0.0f, 0.0f}}});

  test::run_steps(node, 75);  // warm-up: pipelines, first allocations
  const double before = test::resident_mib();
  test::run_steps(node, 300);
  const double growth = test::resident_mib() - before;
  // Before the fix this run grew by about 900 MiB; allocator noise is a few MiB.
  check_growth(growth, "300 steps", 48.0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a long raymarched 3D capture does not grow host memory", "[gpu][liquid][resources]") {
  SKIP_UNDER_ADDRESS_SANITIZER();
  // One step and one small frame (raymarch with obstacles, then FXAA) per frame, as liquid_capture
  // draws them: 250 frames after a warm-up of 20.
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, busy_small_3d(), liquid::LiquidOptions{.frames_in_flight = 1, .max_steps_per_frame = 1});
  liquid::LiquidRenderer renderer(context, node, liquid::RenderSettings{.width = 64, .height = 48});
  const liquid::CameraView camera = liquid::default_camera(node);
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  const double growth = resident_growth(20, 250, [&] {
    test::run_graph(graph, cmd, [&] { renderer.add_to(graph, node.add_to(graph, 1), camera); });
  });
  // With the bisection's count read from the view's uniform block this grew by about 2.7 MiB per
  // frame (some 670 MiB here).
  check_growth(growth, "250 frames", 24.0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a long 2D run checked after every step does not grow host memory", "[gpu][liquid][resources]") {
  SKIP_UNDER_ADDRESS_SANITIZER();
  // As liquid_run runs it: one graph and command buffer, a submission of one step, then diagnose()
  // (three read-backs), 1000 times after a warm-up of 50. Each read-back used to allocate a fresh
  // command buffer, of which lavapipe kept about 3 KB for good: 11.8 MiB here (dam_break_2d grew
  // 7 MB in 150,000 steps). What is left is about 1 KB per diagnose() (docs/memory.md).
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("rest_pool_2d"));
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  const double growth = resident_growth(50, 1000, [&] {
    test::run_frame(node, graph, cmd, 1);
    node.diagnose();
  });
  check_growth(growth, "1000 steps and checks", 4.0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
