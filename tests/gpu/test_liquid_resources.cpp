// Host resources of a long run: stepping must not grow the process's memory. Lavapipe used to
// allocate about 3 MB more per 3D solver step (a 16-frame demo ended near 8 GB) until the solver's
// shaders were specialized for the scene's features (shaders/liquid/common.glsl); this keeps it so.
#include "liquid/node.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

namespace {

// Resident set size of this process in MiB, from /proc/self/status (Linux).
double resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      double kib = 0.0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 12, '\n');
  }
  FAIL("no VmRSS in /proc/self/status");
  return 0.0;
}

}  // namespace

TEST_CASE("a long 3D run with obstacles, an emitter and a force brush does not grow host memory", "[gpu][liquid][resources]") {
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
  liquid::LiquidNode node(test::gpu(), scene);
  node.set_brushes({{.position = {0.1f, 0.1f, 0.12f}, .radius = 0.08f, .acceleration = {2.0f, 0.0f, 0.0f}}});

  test::run_steps(node, 75);  // warm-up: pipelines, first allocations
  const double before = resident_mib();
  test::run_steps(node, 300);
  const double growth = resident_mib() - before;
  // Before the fix this run grew by about 900 MiB; allocator noise is a few MiB.
  INFO("resident set grew by " << growth << " MiB over 300 steps");
  CHECK(growth < 48.0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
