// The PIC/FLIP blend as a rate (liquid/physics/pic_blend.h): the scene key, the arithmetic, and the
// uniform block's blend for the step it is built for.
#include "liquid/physics/pic_blend.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/uniforms.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace liquid;
using Catch::Contains;
using Json = nlohmann::json;

namespace {

Json valid_2d() {
  return Json::parse(R"({"dimension": 2, "domain": [1.0, 0.6], "particle_spacing": 0.01, "pic_ratio": 0.05,
                         "time_step": 0.0004, "fluid_blocks": [{"min": [0.0, 0.0], "max": [0.3, 0.45]}]})");
}

Scene parse(const Json& j) { return parse_scene(j.dump(), "dam.json"); }

// What is left of a particle's deviation from the grid velocity after `seconds` of steps of `dt`.
double deviation_left(double r, double reference, double dt, double seconds) {
  return std::pow(1.0 - pic_blend_for_step(r, reference, dt), seconds / dt);
}

}  // namespace

TEST_CASE("pic_ratio_reference_step: the scene key and its bounds", "[scene][pic]") {
  CHECK_FALSE(parse(valid_2d()).pic_ratio_reference_step);
  Json j = valid_2d();
  j["pic_ratio_reference_step"] = 5e-5;
  REQUIRE(parse(j).pic_ratio_reference_step);
  CHECK(*parse(j).pic_ratio_reference_step == 5e-5f);
  CHECK(make_setup(parse(j), {}).pic_ratio_reference_step == 5e-5f);
  CHECK(make_setup(parse(valid_2d()), {}).pic_ratio_reference_step == 0.0f);
  j["pic_ratio_reference_step"] = 0.0;
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: pic_ratio_reference_step: must be in [1e-06, 0.1], got 0"));
  j["pic_ratio_reference_step"] = "auto";
  CHECK_THROWS_WITH(parse(j), Contains("dam.json: pic_ratio_reference_step"));
}

TEST_CASE("the PIC/FLIP blend damps the same per second whatever the step", "[pic]") {
  // The chapter's blend per step: the damping per second grows with the number of steps.
  CHECK(pic_blend_for_step(0.05, 0.0, 8e-4) == 0.05);
  CHECK(deviation_left(0.05, 0.0, 1e-4, 0.1) < 0.5 * deviation_left(0.05, 0.0, 8e-4, 0.1));
  // Given its reference step, r holds at that step and the decay per second is the same at any step.
  CHECK(pic_blend_for_step(0.05, 1e-4, 1e-4) == Approx(0.05));
  const double at_reference = deviation_left(0.05, 1e-4, 1e-4, 0.1);
  for (double dt : {2.5e-5, 3e-4, 8e-4, 1.6e-3}) {
    INFO("dt " << dt);
    CHECK(deviation_left(0.05, 1e-4, dt, 0.1) == Approx(at_reference).epsilon(1e-9));
  }
  CHECK(pic_blend_for_step(0.05, 1e-4, 8e-4) == Approx(1.0 - std::pow(0.95, 8.0)));
  // Pure PIC and pure FLIP stay what they are.
  CHECK(pic_blend_for_step(1.0, 1e-4, 8e-4) == 1.0);
  CHECK(pic_blend_for_step(0.0, 1e-4, 8e-4) == 0.0);
}

TEST_CASE("the uniform block carries the blend for the step it is built for", "[uniforms][pic]") {
  Json j = valid_2d();
  StepInputs step;
  step.dt = 4e-4f;
  CHECK(make_uniforms(parse(j), make_setup(parse(j), {}), step).pic_ratio == 0.05f);
  j["pic_ratio_reference_step"] = 5e-5;
  const Scene scene = parse(j);
  const SimulationSetup setup = make_setup(scene, {});
  CHECK(make_uniforms(scene, setup, step).pic_ratio == Approx(1.0 - std::pow(0.95, 8.0)).epsilon(1e-5));
  step.dt = 5e-5f;
  CHECK(make_uniforms(scene, setup, step).pic_ratio == Approx(0.05).epsilon(1e-5));
}
