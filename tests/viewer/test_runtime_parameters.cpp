// LiquidNode::set_runtime_parameters, what the viewer's sliders call: the new values reach the
// next steps of a running node (no restart), and bad values are refused by name.
#include "liquid/node.h"
#include "liquid/physics/time_step.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

TEST_CASE("runtime parameters change a running node's next steps and refuse bad values", "[gpu][liquid][viewer]") {
  liquid::LiquidNode node(test::gpu(), test::shipped_scene("dam_break_2d"));
  const liquid::LiquidNode::RuntimeParameters start = node.runtime_parameters();
  CHECK(start.gravity.y == Approx(-9.81f));
  CHECK(start.pic_ratio == Approx(node.scene().pic_ratio));
  CHECK(start.stiffness == Approx(node.scene().stiffness));

  const float start_y = test::run_steps(node, 1).center_of_mass.y;
  const float fallen_y = test::run_steps(node, 100).center_of_mass.y;
  CHECK(fallen_y < start_y);  // under the scene's gravity the column sinks

  liquid::LiquidNode::RuntimeParameters up = start;
  up.gravity = {0.0f, 40.0f, 0.0f};
  up.pic_ratio = 0.5f;
  node.set_runtime_parameters(up);
  CHECK(node.runtime_parameters().gravity.y == 40.0f);
  CHECK(node.runtime_parameters().pic_ratio == 0.5f);
  const liquid::Diagnostics lifted = test::run_steps(node, 200);
  INFO("centre of mass y: start " << start_y << ", after 100 steps " << fallen_y << ", after 200 more "
                                  << lifted.center_of_mass.y);
  CHECK(lifted.center_of_mass.y > start_y + 0.002f);  // gravity pointing up lifts it
  CHECK(lifted.outside_domain == 0);

  liquid::LiquidNode::RuntimeParameters bad = start;
  bad.pic_ratio = 1.5f;
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), liquid::ArgumentError);
  bad = start;
  bad.stiffness = -1.0f;
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), liquid::ArgumentError);
  bad = start;
  bad.gravity.x = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), liquid::ArgumentError);
  CHECK(node.runtime_parameters().gravity.y == 40.0f);  // a refused value changes nothing
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// The panel's slider ranges (LiquidNode::runtime_parameter_range) at their ends, on dam_break_2d with
// the liquid moving (the column collapsed for 0.45 s first): every end runs on stable, and the old
// gravity slider's end, 30 m/s^2, is outside the range.
TEST_CASE("every end of the viewer's slider ranges runs stable at dam_break_2d's step", "[gpu][liquid][viewer]") {
  liquid::LiquidNode node(test::gpu(), test::shipped_scene("dam_break_2d"));
  const liquid::LiquidNode::RuntimeParameters start = node.runtime_parameters();
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  const liquid::RuntimeParameterRange range = node.runtime_parameter_range(start);
  INFO("|g| <= " << range.max_gravity << " m/s^2, k in [" << range.min_stiffness << ", " << range.max_stiffness << "]");
  CHECK(range.max_gravity < 30.0f);  // the old slider's end
  CHECK(range.max_gravity > glm::length(start.gravity));
  CHECK(range.min_stiffness < start.stiffness);
  CHECK(range.max_stiffness > start.stiffness);

  test::run_steps(node, 500);
  const liquid::LiquidNode::Checkpoint moving = node.save_checkpoint();
  const auto at_stiffness = [&](float k) {
    liquid::LiquidNode::RuntimeParameters at = start;
    at.stiffness = k;
    return node.runtime_parameter_range(at);
  };
  const float middle = 0.5f * (start.stiffness + range.max_stiffness);
  struct End {
    const char* name;
    glm::vec3 gravity;
    float stiffness, pic_ratio;
  };
  const float g = range.max_gravity, diagonal = g / std::sqrt(2.0f);
  const std::vector<End> ends = {
      {"gravity up", {0.0f, g, 0.0f}, start.stiffness, start.pic_ratio},
      {"gravity sideways", {-g, 0.0f, 0.0f}, start.stiffness, start.pic_ratio},
      {"gravity diagonal", {diagonal, -diagonal, 0.0f}, start.stiffness, start.pic_ratio},
      {"stiffest", start.gravity, range.max_stiffness, start.pic_ratio},
      {"stiffer, with the gravity it allows, up", {0.0f, at_stiffness(middle).max_gravity, 0.0f}, middle, start.pic_ratio},
      {"softest", start.gravity, range.min_stiffness, start.pic_ratio},
      {"FLIP", start.gravity, start.stiffness, 0.0f},
      {"PIC", start.gravity, start.stiffness, 1.0f},
  };
  for (const End& end : ends) {
    node.restore_checkpoint(moving);
    node.set_runtime_parameters({end.gravity, end.pic_ratio, end.stiffness});
    double most = 0.0;
    float fastest = 0.0f;
    for (int i = 0; i < 6; ++i) {
      liquid::Diagnostics d;
      REQUIRE_NOTHROW(d = test::run_steps(node, 100));
      most = std::max(most, d.kinetic_energy);
      fastest = std::max(fastest, d.max_speed);
    }
    std::printf("%s: g (%g, %g), k %g, PIC %g: kinetic energy at most %g J, speed at most %g m/s\n", end.name,
                end.gravity.x, end.gravity.y, end.stiffness, end.pic_ratio, most, fastest);
    INFO(end.name << ": kinetic energy at most " << most << " J, speed " << fastest << " m/s");
    // Bounded: at most what a fall across the whole domain at this gravity gives all the liquid.
    const double fall = node.diagnose().mass * glm::length(end.gravity) * std::max(setup.domain.x, setup.domain.y);
    CHECK(most < fall);
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}
