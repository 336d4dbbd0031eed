// Dynamic obstacles and rotations on the CPU: the scene keys and their refusals, a body's mass and
// inertia from its shape, and a rotated box's signed distance.
#include "liquid/physics/body.h"
#include "liquid/physics/obstacles.h"
#include "liquid/scene.h"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using Catch::Contains;
using Json = nlohmann::json;

namespace {

// A 2D pool (the splat-adjoint pressure, which dynamic bodies need) with one box obstacle whose
// keys are `box` (merged over a plain box).
Json pool_with(const Json& box, int dimension = 2) {
  Json j = Json::parse(R"({ "dimension": 2, "domain": [1.0, 0.6], "particle_spacing": 0.01,
                            "pressure_force": "splat_adjoint",
                            "fluid_blocks": [{ "min": [0.0, 0.0], "max": [1.0, 0.2] }] })");
  Json obstacle = {{"shape", "box"}, {"center", {0.5, 0.3}}, {"half_extent", {0.1, 0.05}}};
  if (dimension == 3) {
    j["dimension"] = 3;
    j["domain"] = {1.0, 0.6, 0.5};
    j["fluid_blocks"][0] = {{"min", {0.0, 0.0, 0.0}}, {"max", {1.0, 0.2, 0.5}}};
    obstacle["center"] = {0.5, 0.3, 0.25};
    obstacle["half_extent"] = {0.1, 0.05, 0.1};
  }
  if (box.is_object()) obstacle.update(box);
  j["obstacles"] = Json::array({obstacle});
  return j;
}

liquid::Scene parse(const Json& j) { return liquid::parse_scene(j.dump(), "pool.json"); }

}  // namespace

TEST_CASE("a dynamic obstacle is read with its density or mass and a rotation", "[scene][bodies]") {
  const liquid::Scene scene = parse(pool_with({{"dynamic", true}, {"density", 500}, {"rotation", {{"degrees", 30}}}}));
  const liquid::Obstacle& box = scene.obstacles.at(0);
  CHECK(box.dynamic);
  CHECK(box.density == 500.0f);
  CHECK(glm::degrees(glm::angle(box.rotation)) == Approx(30.0f));
  CHECK(glm::axis(box.rotation).z == Approx(1.0f));
  // 2D masses are per metre of depth: 500 kg/m^3 * 0.2 m * 0.1 m.
  CHECK(liquid::body_mass(box, 2) == Approx(10.0));
  CHECK(liquid::body_inertia(box, 2).z == Approx(10.0 * (0.01 + 0.0025) / 3.0));

  const liquid::Scene heavy = parse(pool_with({{"dynamic", true}, {"mass", 3.5}}, 3));
  CHECK(liquid::body_mass(heavy.obstacles.at(0), 3) == Approx(3.5));
}

TEST_CASE("bad dynamic and rotation keys are refused naming the field", "[scene][bodies]") {
  const auto refused = [](const Json& keys, const std::string& message, int dimension = 2) {
    INFO(keys.dump());
    REQUIRE_THROWS_WITH(parse(pool_with(keys, dimension)), Contains(message));
  };
  refused({{"dynamic", true}}, "pool.json: obstacles[0].density: missing required key");
  refused({{"dynamic", true}, {"density", 0}}, "obstacles[0].density: must be in (0, 100000]");
  refused({{"dynamic", true}, {"density", -5}}, "obstacles[0].density: must be in (0, 100000]");
  refused({{"dynamic", true}, {"density", 500}, {"mass", 2}}, "obstacles[0].mass: give density or mass, not both");
  refused({{"density", 500}}, "obstacles[0].density: only allowed with \"dynamic\": true");
  refused({{"dynamic", "yes"}, {"density", 500}}, "obstacles[0].dynamic: must be true or false");
  refused({{"dynamic", true}, {"density", 500}, {"oscillation", {{"amplitude", {0.1, 0}}, {"frequency", 1}}}},
          "obstacles[0].oscillation: not allowed on a dynamic obstacle");
  refused({{"dynamic", true}, {"densty", 500}}, "obstacles[0].densty: unknown key");
  refused({{"rotation", {{"degrees", 10}, {"axis", {1, 0, 0}}}}}, "obstacles[0].rotation.axis: must be [0, 0, 1] in 2D");
  refused({{"rotation", {{"degrees", 10}}}}, "obstacles[0].rotation.axis: missing required key", 3);
  refused({{"rotation", {{"degrees", 10}, {"axis", {0, 0, 0}}}}}, "obstacles[0].rotation.axis: must be nonzero", 3);

  Json balls = pool_with(Json::object());
  balls["obstacles"][0] = {{"shape", "metaballs"}, {"balls", {{{"center", {0.5, 0.3}}, {"radius", 0.1}}}},
                           {"dynamic", true}, {"density", 500}};
  REQUIRE_THROWS_WITH(parse(balls), Contains("obstacles[0].dynamic: metaball obstacles cannot be dynamic"));
  Json chapter = pool_with({{"dynamic", true}, {"density", 500}});
  chapter["pressure_force"] = "chapter";
  REQUIRE_THROWS_WITH(parse(chapter), Contains("obstacles[0].dynamic: needs \"pressure_force\": \"splat_adjoint\""));
}

TEST_CASE("a rotated box's signed distance is taken in its own frame", "[bodies]") {
  liquid::Obstacle box;
  box.shape = liquid::ObstacleShape::Box;
  box.half_extent = {0.2f, 0.05f, 0.1f};
  liquid::ObstaclePose pose;
  pose.center = {0.5f, 0.3f, 0.0f};
  pose.orientation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));  // its long side now along y
  CHECK(liquid::obstacle_distance(box, pose, {0.5f, 0.45f, 0.0f}, 2) == Approx(-0.05f).margin(1e-5));
  CHECK(liquid::obstacle_distance(box, pose, {0.6f, 0.3f, 0.0f}, 2) == Approx(0.05f).margin(1e-5));
  // Inside a 2D rectangle the distance is negative (the z extent plays no part).
  CHECK(liquid::obstacle_distance(box, pose, pose.center, 2) == Approx(-0.05f).margin(1e-5));
  // A point of the turning body moves at v + w x r.
  pose.angular_velocity = {0.0f, 0.0f, 2.0f};
  const glm::vec3 v = liquid::obstacle_velocity_at(pose, pose.center + glm::vec3(0.1f, 0.0f, 0.0f));
  CHECK(v.x == Approx(0.0f).margin(1e-6));
  CHECK(v.y == Approx(0.2f));
}
