// Energy diagnostics on the CPU: potential energy from the domain's floor along gravity, and the
// mechanical energy as kinetic plus potential.
#include "liquid/analysis/diagnostics.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"

#include <catch2/catch.hpp>

namespace {

liquid::SimulationSetup pool(glm::vec3 gravity) {
  liquid::SimulationSetup s;
  s.dimension = 2;
  s.domain = {1.0f, 0.5f, 0.01f};
  s.particle_mass = 2.0f;
  s.gravity = gravity;
  return s;
}

}  // namespace

TEST_CASE("potential energy is measured from the domain's floor along gravity", "[energy]") {
  const liquid::Scene scene;
  liquid::ParticleSnapshot particles;
  particles.positions = {{0.2f, 0.0f, 0.0f, 1.0f}, {0.5f, 0.25f, 0.0f, 1.0f}};
  particles.velocities = {{0.0f, 0.0f, 0.0f, 0.0f}, {3.0f, 4.0f, 0.0f, 0.0f}};
  // Down: m g y; the particle on the floor holds none.
  const liquid::Diagnostics down =
      liquid::compute_diagnostics(scene, pool({0.0f, -10.0f, 0.0f}), particles, {}, {}, 0, 0.0);
  CHECK(down.potential_energy == Approx(2.0 * 10.0 * 0.25));
  CHECK(down.kinetic_energy == Approx(0.5 * 2.0 * 25.0));
  CHECK(down.mechanical_energy == Approx(down.kinetic_energy + down.potential_energy));
  // Gravity along +x: the "floor" is the wall at x = 1 m.
  const liquid::Diagnostics sideways =
      liquid::compute_diagnostics(scene, pool({10.0f, 0.0f, 0.0f}), particles, {}, {}, 0, 0.0);
  CHECK(sideways.potential_energy == Approx(2.0 * 10.0 * (0.8 + 0.5)));
  // No gravity, no potential energy.
  CHECK(liquid::compute_diagnostics(scene, pool(glm::vec3(0.0f)), particles, {}, {}, 0, 0.0).potential_energy == 0.0);
}

TEST_CASE("pressure_force picks the chapter's or the splat-adjoint pressure gradient", "[energy][scene]") {
  const std::string head = R"({"dimension": 2, "domain": [1.0, 0.5], "particle_spacing": 0.01,
    "fluid_blocks": [{"min": [0.0, 0.0], "max": [0.2, 0.2]}])";
  const liquid::Scene plain = liquid::parse_scene(head + "}", "plain.json");  // the default
  CHECK(plain.pressure_force == liquid::PressureForce::SplatAdjoint);
  CHECK(liquid::make_setup(plain, {}).splat_adjoint_pressure);
  const liquid::Scene chapter = liquid::parse_scene(head + R"(, "pressure_force": "chapter"})", "chapter.json");
  CHECK(chapter.pressure_force == liquid::PressureForce::Chapter);
  CHECK_FALSE(liquid::make_setup(chapter, {}).splat_adjoint_pressure);
  // Shallow water runs the chapter's, whatever a scene built in code holds.
  liquid::Scene shallow = plain;
  shallow.mode = liquid::SimulationMode::ShallowWater;
  CHECK_FALSE(liquid::make_setup(shallow, {}).splat_adjoint_pressure);
  CHECK(liquid::projection_iterations_of(shallow) == 0);
  CHECK_THROWS_WITH(liquid::parse_scene(head + R"(, "pressure_force": "sph"})", "bad.json"),
                    Catch::Contains("pressure_force"));
}
