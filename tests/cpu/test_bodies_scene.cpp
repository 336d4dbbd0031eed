// Dynamic obstacles and rotations on the CPU: the scene keys and their refusals, a body's mass and
// inertia from its shape, and a rotated box's signed distance.
#include "liquid/physics/body.h"
#include "liquid/physics/obstacles.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/scene/limits.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
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
  REQUIRE_THROWS_WITH(parse(balls), Contains("obstacles[0].dynamic: \"metaballs\" obstacles cannot be dynamic"));
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

TEST_CASE("a scripted spin turns an obstacle about its centre at its angular velocity", "[scene][bodies]") {
  const liquid::Scene flat = parse(pool_with({{"angular_velocity", 2.0}, {"rotation", {{"degrees", 30}}}}));
  const liquid::Obstacle& box = flat.obstacles.at(0);
  CHECK(box.angular_velocity == glm::vec3(0.0f, 0.0f, 2.0f));
  const liquid::ObstaclePose pose = liquid::scripted_pose(box, 0.5);
  CHECK(pose.angular_velocity.z == Approx(2.0f));
  CHECK(pose.center == box.center);  // it turns in place
  // 30 degrees from the scene's rotation plus 1 rad.
  CHECK(glm::angle(pose.orientation) == Approx(glm::radians(30.0f) + 1.0f));
  CHECK(glm::axis(pose.orientation).z == Approx(1.0f));

  const liquid::Scene solid = parse(pool_with({{"angular_velocity", {0, -1.5, 0}}}, 3));
  const liquid::ObstaclePose turned = liquid::scripted_pose(solid.obstacles.at(0), 1.0);
  CHECK(glm::angle(turned.orientation) == Approx(1.5f));
  CHECK(glm::axis(turned.orientation).y == Approx(-1.0f));
  // A dynamic obstacle starts turning at it.
  const liquid::Scene body = parse(pool_with({{"angular_velocity", 1.0}, {"dynamic", true}, {"density", 500}}));
  CHECK(liquid::scripted_pose(body.obstacles.at(0), 1.0).angular_velocity.z == Approx(1.0f));
}

TEST_CASE("bad angular velocities are refused naming the field", "[scene][bodies]") {
  const auto refused = [](const Json& keys, const std::string& message, int dimension = 2) {
    INFO(keys.dump());
    REQUIRE_THROWS_WITH(parse(pool_with(keys, dimension)), Contains(message));
  };
  refused({{"angular_velocity", {0, 0, 1}}}, "obstacles[0].angular_velocity: must be one number in 2D (rad/s about z)");
  refused({{"angular_velocity", 1}}, "obstacles[0].angular_velocity: must be an array of numbers", 3);
  refused({{"angular_velocity", {0, 1}}}, "obstacles[0].angular_velocity: must have 3 components", 3);
  refused({{"angular_velocity", 5000}}, "obstacles[0].angular_velocity: must be in [-1000, 1000]");
  refused({{"angular_velocity", {0, "fast", 0}}}, "obstacles[0].angular_velocity[1]: must be a number", 3);
  Json balls = pool_with(Json::object());
  balls["obstacles"][0] = {{"shape", "metaballs"}, {"balls", {{{"center", {0.5, 0.3}}, {"radius", 0.1}}}},
                           {"angular_velocity", 1}};
  REQUIRE_THROWS_WITH(parse(balls), Contains("obstacles[0].angular_velocity: unknown key"));
}

TEST_CASE("the turn between two rotations is the angular velocity that makes it, the shorter way round", "[bodies]") {
  const glm::quat from = glm::angleAxis(0.3f, glm::vec3(0, 1, 0));
  const glm::vec3 w = liquid::turn_rate(from, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)) * from, 0.1);
  CHECK(w.x == Approx(0.0f).margin(1e-5));
  CHECK(w.y == Approx(5.0f).epsilon(1e-4));
  // -q is the same rotation: a turn of 350 degrees one way is 10 degrees the other.
  const glm::vec3 back = liquid::turn_rate(from, -(glm::angleAxis(glm::radians(350.0f), glm::vec3(1, 0, 0)) * from), 1.0);
  CHECK(back.x == Approx(-glm::radians(10.0f)).epsilon(1e-3));
  CHECK(liquid::turn_rate(from, from, 1.0) == glm::vec3(0.0f));
  CHECK(liquid::turn_rate(from, glm::quat(1, 0, 0, 0), 0.0) == glm::vec3(0.0f));
}

TEST_CASE("a closed mesh's volume, centre of mass and inertia are the solid's, exactly for a box", "[bodies][mesh]") {
  // A box of half extents (0.1, 0.05, 0.2) m: V = 8abc, I_x = V (b^2 + c^2) / 3 at unit density.
  const glm::dvec3 e(0.1, 0.05, 0.2);
  liquid::TriangleMesh box = test::box_mesh(glm::vec3(e));
  const liquid::MeshMass m = liquid::mesh_mass_properties(box);
  const double volume = 8.0 * e.x * e.y * e.z;
  CHECK(m.volume == Approx(volume).epsilon(1e-6));
  CHECK(glm::length(m.centroid) == Approx(0.0).margin(1e-7));
  CHECK(m.inertia[0][0] == Approx(volume * (e.y * e.y + e.z * e.z) / 3.0).epsilon(1e-5));
  CHECK(m.inertia[1][1] == Approx(volume * (e.x * e.x + e.z * e.z) / 3.0).epsilon(1e-5));
  CHECK(m.inertia[2][2] == Approx(volume * (e.x * e.x + e.y * e.y) / 3.0).epsilon(1e-5));
  CHECK(std::abs(m.inertia[0][1]) + std::abs(m.inertia[1][2]) + std::abs(m.inertia[0][2]) < 1e-9);

  // Moved off its origin, turned and scaled: the same solid about its own centre, the centroid where it went.
  const glm::dquat turn = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1.0, 2.0, -0.5)));
  for (glm::vec3& v : box.vertices) v = glm::vec3(turn * glm::dvec3(v) + glm::dvec3(0.3, -0.1, 0.05));
  box.scale = 2.0f;
  const liquid::MeshMass moved = liquid::mesh_mass_properties(box);
  CHECK(moved.volume == Approx(8.0 * volume).epsilon(1e-6));
  CHECK(moved.centroid.x == Approx(0.6).epsilon(1e-5));
  CHECK(moved.centroid.y == Approx(-0.2).epsilon(1e-5));
  const liquid::PrincipalAxes principal = liquid::principal_axes(moved.inertia);
  // Its principal moments are the box's at twice the size (32 times: volume 8, lengths squared 4).
  glm::dvec3 sorted = principal.moments, expected(m.inertia[0][0], m.inertia[1][1], m.inertia[2][2]);
  std::sort(&sorted[0], &sorted[0] + 3);
  std::sort(&expected[0], &expected[0] + 3);
  for (int a = 0; a < 3; ++a) CHECK(sorted[a] == Approx(32.0 * expected[a]).epsilon(1e-5));
  // And R diag(moments) R^T gives the tensor back.
  const glm::dmat3 r = glm::mat3_cast(principal.axes);
  const glm::dmat3 back = r * glm::dmat3(principal.moments.x, 0, 0, 0, principal.moments.y, 0, 0, 0, principal.moments.z) *
                          glm::transpose(r);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) CHECK(back[c][k] == Approx(moved.inertia[c][k]).margin(1e-9 * moved.inertia[0][0]));
}

TEST_CASE("a mesh sphere's mass properties are the sphere's within its facets' error", "[bodies][mesh]") {
  const double r = 0.05;
  const liquid::MeshMass m = liquid::mesh_mass_properties(test::icosphere(float(r), 4));
  const double volume = 4.0 / 3.0 * M_PI * r * r * r;
  CHECK(m.volume == Approx(volume).epsilon(0.005));
  CHECK(m.inertia[1][1] == Approx(0.4 * volume * r * r).epsilon(0.01));
  CHECK(glm::length(m.centroid) < 1e-6);
}

TEST_CASE("a dynamic mesh is re-expressed about its centre of mass and principal axes, staying where it was",
          "[bodies][mesh]") {
  liquid::Obstacle o;
  o.shape = liquid::ObstacleShape::Mesh;
  o.dynamic = true;
  o.density = 500.0f;
  o.center = {0.5f, 0.3f, 0.25f};
  o.mesh = test::box_mesh({0.1f, 0.04f, 0.06f});
  for (glm::vec3& v : o.mesh.vertices) v += glm::vec3(0.02f, 0.0f, -0.01f);  // its origin off the centre of mass
  o.mesh.rotation = o.rotation = glm::angleAxis(0.4f, glm::vec3(0.0f, 0.0f, 1.0f));
  const liquid::Obstacle body = liquid::mesh_body_in_principal_frame(o);
  for (size_t i = 0; i < o.mesh.vertices.size(); ++i) {
    const glm::vec3 before = o.center + o.mesh.rotation * (o.mesh.scale * o.mesh.vertices[i]);
    const glm::vec3 after = body.center + body.mesh.rotation * (body.mesh.scale * body.mesh.vertices[i]);
    CHECK(glm::distance(before, after) < 1e-5f);
  }
  CHECK(glm::length(liquid::mesh_mass_properties(body.mesh).centroid) < 1e-6);
  CHECK(liquid::body_mass(body, 3) == Approx(500.0 * 8 * 0.1 * 0.04 * 0.06).epsilon(1e-5));
  // The box's moments, as the analytic box's.
  liquid::Obstacle analytic;
  analytic.shape = liquid::ObstacleShape::Box;
  analytic.half_extent = {0.1f, 0.04f, 0.06f};
  analytic.density = 500.0f;
  glm::vec3 mesh_moments = liquid::body_inertia(body, 3), box_moments = liquid::body_inertia(analytic, 3);
  std::sort(&mesh_moments[0], &mesh_moments[0] + 3);
  std::sort(&box_moments[0], &box_moments[0] + 3);
  for (int a = 0; a < 3; ++a) CHECK(mesh_moments[a] == Approx(box_moments[a]).epsilon(1e-4));
  CHECK(liquid::body_volume(body, 3) == Approx(liquid::body_volume(analytic, 3)).epsilon(1e-5));
  CHECK(liquid::body_surface(body, 3) == Approx(liquid::body_surface(analytic, 3)).epsilon(1e-5));
}

TEST_CASE("a dynamic mesh is refused in 2D, from a scene file or built in code", "[scene][bodies][mesh]") {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "liquid_dynamic_mesh_2d";
  std::filesystem::create_directories(dir);
  {
    std::ofstream obj(dir / "box.obj");
    for (const glm::vec3& v : test::box_mesh(glm::vec3(0.05f)).vertices) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
    const std::vector<uint32_t> f = test::box_mesh(glm::vec3(0.05f)).indices;
    for (size_t t = 0; t < f.size(); t += 3) obj << "f " << f[t] + 1 << " " << f[t + 1] + 1 << " " << f[t + 2] + 1 << "\n";
  }
  Json j = pool_with(Json::object());
  j["obstacles"][0] = {{"shape", "mesh"}, {"file", "box.obj"}, {"center", {0.5, 0.3}}, {"dynamic", true}, {"density", 500}};
  REQUIRE_THROWS_WITH(liquid::parse_scene(j.dump(), (dir / "pool.json").string()),
                      Contains("obstacles[0].dynamic: a mesh obstacle can be dynamic in 3D only"));
  // In 3D it is read, its mass the mesh's volume times its density.
  Json solid = pool_with(Json::object(), 3);
  solid["obstacles"][0] = {{"shape", "mesh"}, {"file", "box.obj"}, {"center", {0.5, 0.3, 0.25}}, {"dynamic", true}, {"density", 500}};
  const liquid::Scene scene = liquid::parse_scene(solid.dump(), (dir / "pool.json").string());
  CHECK(scene.obstacles.at(0).dynamic);
  CHECK(liquid::body_mass(scene.obstacles.at(0), 3) == Approx(500.0 * 0.001).epsilon(1e-5));
  // A host's 2D scene with a dynamic mesh.
  liquid::Scene host = parse(pool_with(Json::object()));
  host.obstacles[0].shape = liquid::ObstacleShape::Mesh;
  host.obstacles[0].mesh = test::box_mesh(glm::vec3(0.05f));
  host.obstacles[0].dynamic = true;
  host.obstacles[0].density = 500.0f;
  REQUIRE_THROWS_WITH(liquid::check_list_limits(host), Contains("obstacles[0].dynamic: a mesh obstacle can be dynamic in 3D only"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a body outside the domain or wider than it and an inside-out mesh are refused by name",
          "[scene][bodies][mesh]") {
  // The setup checks the bodies, with the box the wall contact keeps inside the domain.
  const auto refused = [](const Json& keys, const std::string& message, int dimension = 2) {
    INFO(keys.dump());
    REQUIRE_THROWS_WITH(liquid::make_setup(parse(pool_with(keys, dimension)), {}), Contains(message));
  };
  refused({{"dynamic", true}, {"density", 500}, {"center", {5.0, 5.0, 5.0}}},
          "pool.json: obstacles[0]: the dynamic box reaches x = 5.1 m, outside the domain's [0, 1] m", 3);
  refused({{"dynamic", true}, {"density", 500}, {"center", {0.5, 0.02}}},
          "obstacles[0]: the dynamic box reaches y = -0.03 m, outside the domain's [0, 0.6] m");
  refused({{"dynamic", true}, {"density", 500}, {"half_extent", {0.7, 0.01, 0.1}}},
          "obstacles[0]: the dynamic box is 1.4 m across along x, wider than the domain's 1 m", 3);
  // Turned 45 degrees, the 0.2 x 0.1 m box reaches (0.1 + 0.05) / sqrt(2) = 0.106 m from its centre.
  refused({{"dynamic", true}, {"density", 500}, {"center", {0.1, 0.3}}, {"rotation", {{"degrees", 45}}}},
          "reaches x = -0.006");
  CHECK_NOTHROW(liquid::make_setup(
      parse(pool_with({{"dynamic", true}, {"density", 500}, {"center", {0.11, 0.3}}, {"rotation", {{"degrees", 45}}}})), {}));
  Json sphere = pool_with(Json::object());
  sphere["obstacles"][0] = {{"shape", "sphere"}, {"radius", 0.1}, {"dynamic", true}, {"density", 500}, {"center", {0.5, 0.55}}};
  REQUIRE_THROWS_WITH(liquid::make_setup(parse(sphere), {}), Contains("the dynamic sphere reaches y = 0.65 m"));
  // Resting on the floor, and static obstacles anywhere, are fine.
  CHECK_NOTHROW(liquid::make_setup(parse(pool_with({{"dynamic", true}, {"density", 500}, {"center", {0.5, 0.05}}})), {}));
  CHECK_NOTHROW(liquid::make_setup(parse(pool_with({{"center", {5.0, 5.0}}})), {}));

  // A dynamic mesh: its principal box turned, as the wall contact sees it.
  liquid::Scene host = parse(pool_with(Json::object(), 3));
  liquid::Obstacle& mesh = host.obstacles[0];
  mesh.shape = liquid::ObstacleShape::Mesh;
  mesh.mesh = test::box_mesh({0.1f, 0.05f, 0.1f});
  mesh.dynamic = true;
  mesh.density = 500.0f;
  mesh.center = {0.5f, 0.56f, 0.25f};
  REQUIRE_THROWS_WITH(liquid::make_setup(host, {}), Contains("the dynamic mesh's box about its centre of mass (what the walls hold in) reaches y = 0.61 m"));
  mesh.center.y = 0.3f;
  CHECK_NOTHROW(liquid::make_setup(host, {}));

  // A host's mesh wound inward, static or dynamic.
  CHECK_NOTHROW(liquid::check_list_limits(host));
  std::vector<uint32_t>& indices = mesh.mesh.indices;
  for (size_t t = 0; t < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
  REQUIRE_THROWS_WITH(liquid::check_list_limits(host), Contains("obstacles[0]: the host's mesh: is inside out"));
  mesh.dynamic = false;
  REQUIRE_THROWS_WITH(liquid::make_setup(host, {}), Contains("is inside out"));
}
