// Adaptive time steps on the CPU: the scene key, and the CFL step for a state (liquid/physics/time_step.h).
#include "liquid/physics/setup.h"
#include "liquid/physics/time_step.h"
#include "liquid/scene.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

using namespace liquid;
using Catch::Contains;
using Json = nlohmann::json;

namespace {

Json valid_2d() {
  return Json::parse(R"({"dimension": 2, "domain": [1.0, 0.6], "particle_spacing": 0.01,
                         "fluid_blocks": [{"min": [0.0, 0.0], "max": [0.3, 0.45]}]})");
}

Scene parse(const Json& j) { return parse_scene(j.dump(), "dam.json"); }

SimulationSetup setup_with(float stiffness, float gamma, float cell) {
  SimulationSetup s;
  s.stiffness = stiffness;
  s.gamma = gamma;
  s.cell_size = cell;
  return s;
}

Diagnostics state(float max_speed, float max_density_ratio) {
  Diagnostics d;
  d.max_speed = max_speed;
  d.max_density_ratio = max_density_ratio;
  return d;
}

}  // namespace

TEST_CASE("adaptive_time_step: the scene key, its defaults and its bounds", "[scene][time_step]") {
  CHECK_FALSE(parse(valid_2d()).adaptive_time_step);
  Json j = valid_2d();
  j["adaptive_time_step"] = Json::object();
  const Scene defaults = parse(j);
  REQUIRE(defaults.adaptive_time_step);
  CHECK(defaults.adaptive_time_step->acoustic_cfl == 0.16f);
  CHECK(defaults.adaptive_time_step->velocity_cfl == 0.4f);
  j["adaptive_time_step"] = {{"acoustic_cfl", 0.3}, {"velocity_cfl", 1.0}};
  CHECK(parse(j).adaptive_time_step->acoustic_cfl == 0.3f);
  CHECK(parse(j).adaptive_time_step->velocity_cfl == 1.0f);

  j["adaptive_time_step"] = {{"acoustic_cfl", 0.0}};
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: adaptive_time_step.acoustic_cfl: must be in (0, 2], got 0"));
  j["adaptive_time_step"] = {{"velocity_cfl", 3}};
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: adaptive_time_step.velocity_cfl: must be in (0, 2], got 3"));
  // Past the chapter's regime only with the twice-smoothed pressure, and with the PIC blend per
  // second or the projection (the default).
  j["adaptive_time_step"] = {{"acoustic_cfl", 1.3}};
  CHECK(parse(j).adaptive_time_step->acoustic_cfl == 1.3f);
  j["pressure_force"] = "chapter";
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: adaptive_time_step.acoustic_cfl: above 1 needs \"pressure_force\": "
                                       "\"splat_adjoint\" with pic_ratio_reference_step or the projection, got 1.3"));
  j["pressure_force"] = "splat_adjoint";
  j["projection_iterations"] = 0;
  j["pic_ratio_reference_step"] = 1e-4;
  CHECK(parse(j).adaptive_time_step->acoustic_cfl == 1.3f);
  j.erase("pressure_force");
  j.erase("pic_ratio_reference_step");
  j["adaptive_time_step"] = {{"acoustic", 0.1}};
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: adaptive_time_step.acoustic: unknown key"));
  j["adaptive_time_step"] = 0.1;
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: adaptive_time_step"));
}

TEST_CASE("the CFL step: acoustic while the liquid is slow, by velocity when fast, never above the largest",
          "[time_step]") {
  const SimulationSetup s = setup_with(20.0f, 5.0f, 0.004f);
  const AdaptiveTimeStep cfl{0.16f, 0.4f};
  // c = sqrt(k gamma) = 10 m/s at rest density; nothing moving: dt = 0.16 h / c.
  CHECK(speed_of_sound(s, 1.0) == Approx(10.0));
  CHECK(speed_of_sound(s, 0.5) == Approx(10.0));  // below rho0 the clamp leaves P = 0: still c0
  CHECK(cfl_time_step(s, cfl, state(0.0f, 1.0f), 1.0) == Approx(0.16 * 0.004 / 10.0));
  // Compressed by 10 %: c = 10 * 1.1^2.5.
  CHECK(cfl_time_step(s, cfl, state(0.0f, 1.1f), 1.0) == Approx(0.16 * 0.004 / (10.0 * std::pow(1.1, 2.5))));
  // 2 m/s: the acoustic bound adds the flow to c.
  CHECK(cfl_time_step(s, cfl, state(2.0f, 1.0f), 1.0) == Approx(0.16 * 0.004 / 12.0));
  // 50 m/s (a splash past the sound speed): the velocity bound, 0.4 h / u, is lower still.
  CHECK(cfl_time_step(s, AdaptiveTimeStep{0.9f, 0.4f}, state(50.0f, 1.0f), 1.0) == Approx(0.4 * 0.004 / 50.0));
  // Capped at the largest step, and never NaN from a non-finite state.
  CHECK(cfl_time_step(s, cfl, state(0.0f, 1.0f), 1e-5) == 1e-5);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK(std::isfinite(cfl_time_step(s, cfl, state(nan, nan), 1.0)));
}
