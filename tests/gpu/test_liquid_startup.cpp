// The first steps of a scene: liquid that starts next to an obstacle or a wall starts at rest. An
// obstacle's artificial density (section 6) reaches one kernel radius into the liquid; lattice
// points left in that band were blasted away (a block around a sphere reached 6 m/s in 20 steps,
// against 0.026 m/s of free fall without it), so the setup carves the blocks out to most of the
// band. At a wall, a block floating against it reached 0.43 m/s at its corners, from the wall
// coverage's over-read and the margin clamp's snap (docs/physics.md, "Start-up next to a wall").
#include "liquid/node.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

constexpr int k_steps = 20;

// A block floating in the middle of the domain (touching no wall, so only the obstacle acts on
// it) in the resolution and stiffness of the shipped obstacle scenes.
liquid::Scene floating_block(int dimension) {
  liquid::Scene scene = test::with_chapter_model({});  // each test names its pressure force
  scene.name = "floating block " + std::to_string(dimension) + "D";
  scene.dimension = dimension;
  if (dimension == 2) {
    scene.domain = {1.0f, 0.6f, 0.0f};
    scene.gravity = {0.0f, -9.81f, 0.0f};
    scene.grid_resolution = 128;
    scene.particle_spacing = 0.003125f;
    scene.stiffness = 15.312f;
    scene.time_step = 0.0001339f;
    scene.fluid_blocks = {{{0.2f, 0.1f, 0.0f}, {0.45f, 0.4f, 0.0f}, {}}};
  } else {
    scene.domain = {0.5f, 0.3f, 0.25f};
    scene.grid_resolution = 48;
    scene.particle_spacing = 0.0105f;
    scene.stiffness = 9.8f;
    scene.time_step = 0.0002222f;
    scene.fluid_blocks = {{{0.1f, 0.06f, 0.04f}, {0.4f, 0.26f, 0.21f}, {}}};
  }
  scene.substeps = k_steps;
  return scene;
}

liquid::Obstacle sphere(glm::vec3 center, float radius) {
  liquid::Obstacle o;
  o.shape = liquid::ObstacleShape::Sphere;
  o.center = center;
  o.radius = radius;
  return o;
}

liquid::Obstacle box(glm::vec3 center, glm::vec3 half_extent) {
  liquid::Obstacle o;
  o.shape = liquid::ObstacleShape::Box;
  o.center = center;
  o.half_extent = half_extent;
  return o;
}

// The largest particle speed over each of the first k_steps steps.
float max_speed_over_first_steps(const liquid::Scene& scene) {
  liquid::LiquidNode node(test::gpu(), scene);
  REQUIRE(node.active_particles() > 1000);  // the carving leaves most of the block
  float fastest = 0.0f;
  for (int step = 0; step < k_steps; ++step) fastest = std::max(fastest, test::run_steps(node, 1).max_speed);
  return fastest;
}

}  // namespace

TEST_CASE("liquid that starts around an obstacle starts at rest", "[gpu][liquid][physics]") {
  struct Case {
    const char* what;
    int dimension;
    liquid::Obstacle obstacle;
  };
  const Case cases[] = {
      {"2D block around a sphere", 2, sphere({0.3f, 0.25f, 0.0f}, 0.07f)},
      {"2D block around a box", 2, box({0.35f, 0.25f, 0.0f}, {0.05f, 0.04f, 0.0f})},
      {"3D block around a sphere", 3, sphere({0.25f, 0.16f, 0.125f}, 0.03f)},
  };
  for (const auto force : {liquid::PressureForce::Chapter, liquid::PressureForce::SplatAdjoint}) {
    for (const Case& c : cases) {
      liquid::Scene scene = floating_block(c.dimension);
      scene.pressure_force = force;
      scene.obstacles = {c.obstacle};
      // Free fall over those steps, plus a margin for the obstacle's no-penetration condition and
      // the splat's noise; before the carving reached into the band these were 6 m/s.
      const float free_fall = 9.81f * scene.time_step * k_steps;
      const float fastest = max_speed_over_first_steps(scene);
      INFO(c.what << (force == liquid::PressureForce::Chapter ? ", chapter" : ", splat adjoint")
                  << ": fastest particle " << fastest << " m/s over " << k_steps << " steps; free fall " << free_fall
                  << " m/s");
      CHECK(fastest < free_fall + 0.05f);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("liquid that starts against a wall starts at rest", "[gpu][liquid][physics]") {
  // Splat-adjoint pressure (the shipped physical scenes' mode): exact wall coverage, hydrostatic
  // ghost cells beyond the walls, and a clamp that does not snap the lattice's first layer out.
  SECTION("a block floating against the side walls falls freely") {
    for (int dimension : {2, 3}) {
      liquid::Scene scene = floating_block(dimension);
      scene.pressure_force = liquid::PressureForce::SplatAdjoint;
      liquid::FluidBlock& block = scene.fluid_blocks[0];
      block.max.x -= block.min.x;  // against x = 0
      block.min.x = 0.0f;
      if (dimension == 3) {  // and against z = 0: the block stands in a corner
        block.max.z -= block.min.z;
        block.min.z = 0.0f;
      }
      // Measured 0.02627 in 2D (free fall 0.02627) and 0.0504 in 3D (0.0436); the converged
      // integral's coverage instead of the lattice's left 0.036 and 0.10, the 16-interval rule 0.43.
      const float free_fall = 9.81f * scene.time_step * k_steps;
      const float fastest = max_speed_over_first_steps(scene);
      INFO(dimension << "D: fastest particle " << fastest << " m/s over " << k_steps << " steps; free fall "
                     << free_fall << " m/s (0.43 m/s in 2D before the fix)");
      CHECK(fastest < free_fall + (dimension == 2 ? 0.003f : 0.012f));
    }
  }
  SECTION("a pool across the floor stays still from the first step") {
    for (int dimension : {2, 3}) {
      liquid::Scene scene = floating_block(dimension);
      scene.pressure_force = liquid::PressureForce::SplatAdjoint;
      // Wall to wall: a spacing that divides the domain (in 3D one cell, 0.5 / 48 m), the depth a
      // whole number of spacings.
      if (dimension == 3) scene.particle_spacing = scene.domain.x / float(*scene.grid_resolution);
      liquid::FluidBlock& block = scene.fluid_blocks[0];
      block.min = glm::vec3(0.0f);
      block.max = glm::vec3(scene.domain.x, 0.4f * scene.domain.y, dimension == 3 ? scene.domain.z : 0.0f);
      block.max.y = std::round(block.max.y / scene.particle_spacing) * scene.particle_spacing;
      // It starts hydrostatically compressed, so nothing is pushed and the pool as a whole does
      // not fall onto itself: no particle outruns free fall by more than a fifth (the slowest to
      // settle are the bottom corners, where the coverage is a product of the two walls' shares),
      // and the RMS speed stays a small share of free fall (measured 0.13 of it in 2D, 0.24 in 3D;
      // started uncompressed, all but the bottom few centimetres would still be falling freely:
      // the pressure wave from the floor has covered c t = 2.3 cm of the 24 cm in 2D).
      const float free_fall = 9.81f * scene.time_step * k_steps;
      liquid::LiquidNode node(test::gpu(), scene);
      float fastest = 0.0f;
      liquid::Diagnostics d;
      for (int step = 0; step < k_steps; ++step) {
        d = test::run_steps(node, 1);
        fastest = std::max(fastest, d.max_speed);
      }
      const double rms = std::sqrt(2.0 * d.kinetic_energy / d.mass);
      INFO(dimension << "D: fastest particle " << fastest << " m/s, RMS " << rms << " m/s over " << k_steps
                     << " steps; free fall " << free_fall << " m/s");
      CHECK(fastest < 1.2f * free_fall);
      CHECK(rms < 0.4 * free_fall);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}
