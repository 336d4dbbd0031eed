// LiquidNode::set_runtime_parameters, what the viewer's sliders call: the new values reach the
// next steps of a running node (no restart), and bad values are refused by name.
#include "liquid/node.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <limits>
#include <stdexcept>

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
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), std::invalid_argument);
  bad = start;
  bad.stiffness = -1.0f;
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), std::invalid_argument);
  bad = start;
  bad.gravity.x = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_AS(node.set_runtime_parameters(bad), std::invalid_argument);
  CHECK(node.runtime_parameters().gravity.y == 40.0f);  // a refused value changes nothing
  REQUIRE_NO_VALIDATION_MESSAGES();
}
