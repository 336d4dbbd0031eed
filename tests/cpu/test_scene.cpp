// Scene loading with no GPU: every shipped scene parses, defaults and conversions are right, and
// each kind of malformed scene is rejected with a message naming the file and the field.
#include "liquid/scene.h"
#include "liquid/scene/format.h"
#include "liquid/scene/number_keys.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace liquid;
using Catch::Contains;
using Json = nlohmann::json;
using test_scenes::k_scene_dir;

namespace {

const std::vector<std::string> k_shipped_scenes = {
    "dam_break_2d.json", "dam_break_3d.json", "paper_2d_16k.json", "paper_2d_32k.json",
    "paper_2d_64k.json", "paper_3d.json",     "shallow_water.json", "obstacles_2d.json",
    "rest_pool_2d.json", "symmetric_2d.json", "small_3d.json",      "jet_2d.json",
    "column_2d.json",    "column_3d.json",    "dam_break_tank_2d.json", "floating_box_2d.json",
    "floating_boxes_3d.json", "mesh_pool_3d.json", "dam_break_3d_floating.json",
    "dam_break_3d_whitewater.json"};

// A small valid 2D scene; each malformed case changes one thing.
Json valid_2d() {
  return Json::parse(R"({
    "dimension": 2,
    "domain": [1.0, 0.6],
    "particle_spacing": 0.01,
    "fluid_blocks": [{ "min": [0.0, 0.0], "max": [0.3, 0.45] }]
  })");
}

Json valid_3d() {
  Json j = valid_2d();
  j["dimension"] = 3;
  j["domain"] = {1.0, 0.6, 0.5};
  j["fluid_blocks"][0] = {{"min", {0.0, 0.0, 0.0}}, {"max", {0.3, 0.45, 0.5}}};
  return j;
}

Scene parse(const Json& j) { return parse_scene(j.dump(2), "dam.json"); }

// valid_2d() with the value at `pointer` (a JSON pointer, e.g. "/fluid_blocks/0/max") set to `value` (JSON
// text) is refused with a message containing `message`.
void refused_with(const char* pointer, const char* value, const std::string& message) {
  Json j = valid_2d();
  j[Json::json_pointer(pointer)] = Json::parse(value);
  REQUIRE_THROWS_WITH(parse(j), Contains(message));
}

}  // namespace

TEST_CASE("every shipped scene loads", "[scene]") {
  for (const std::string& file : k_shipped_scenes) {
    INFO(file);
    const Scene scene = load_scene(k_scene_dir / file);
    CHECK_FALSE(scene.name.empty());
    CHECK((scene.dimension == 2 || scene.dimension == 3));
    CHECK((!scene.fluid_blocks.empty() || !scene.emitters.empty()));
  }
  // Nothing shipped is left out of the list above (the setup tests walk it too).
  for (const auto& entry : std::filesystem::directory_iterator(k_scene_dir))
    if (entry.path().extension() == ".json") {
      INFO(entry.path().filename().string());
      CHECK(std::find(k_shipped_scenes.begin(), k_shipped_scenes.end(), entry.path().filename().string()) !=
            k_shipped_scenes.end());
    }
}

TEST_CASE("shipped scenes carry what their names promise", "[scene]") {
  const Scene boxes = load_scene(k_scene_dir / "floating_boxes_3d.json");
  REQUIRE(boxes.obstacles.size() == 2);
  CHECK((boxes.obstacles[0].dynamic && boxes.obstacles[0].density < 1000.0f));  // floats
  CHECK((boxes.obstacles[1].dynamic && boxes.obstacles[1].density > 1000.0f));  // sinks
  CHECK(load_scene(k_scene_dir / "floating_box_2d.json").obstacles.at(0).dynamic);
  const Scene obstacles = load_scene(k_scene_dir / "obstacles_2d.json");
  REQUIRE(obstacles.obstacles.size() == 3);
  CHECK(obstacles.obstacles[0].shape == ObstacleShape::Sphere);
  CHECK(obstacles.obstacles[1].shape == ObstacleShape::Box);
  CHECK(obstacles.obstacles[2].shape == ObstacleShape::Metaballs);
  CHECK(obstacles.grid_resolution == 128);

  const Scene shallow = load_scene(k_scene_dir / "shallow_water.json");
  CHECK(shallow.mode == SimulationMode::ShallowWater);
  CHECK(shallow.dimension == 2);
  CHECK(shallow.grid_resolution == 256);
  CHECK_FALSE(shallow.ground.empty());
  CHECK(shallow.rest_depth == Approx(0.05f));

  const Scene paper = load_scene(k_scene_dir / "paper_3d.json");
  CHECK(paper.dimension == 3);
  CHECK(paper.grid_resolution == 96);
  CHECK(paper.camera.has_value());
  CHECK(paper.emitters.size() == 1);
  CHECK(paper.obstacles.size() >= 2);
  for (const Obstacle& o : paper.obstacles) CHECK(o.shape == ObstacleShape::Sphere);

  CHECK(load_scene(k_scene_dir / "dam_break_3d.json").camera.has_value());
  const Scene boat = load_scene(k_scene_dir / "dam_break_3d_floating.json");
  REQUIRE(boat.obstacles.size() == 1);
  CHECK(boat.obstacles[0].shape == ObstacleShape::Mesh);
  CHECK((boat.obstacles[0].dynamic && boat.obstacles[0].density < 1000.0f));  // floats
  CHECK(load_scene(k_scene_dir / "jet_2d.json").emitters.size() == 1);
}

TEST_CASE("omitted fields take their documented defaults", "[scene]") {
  const Scene scene = parse_scene(valid_2d().dump(), "scenes/my_tank.json");
  CHECK(scene.name == "my_tank");
  CHECK(scene.dimension == 2);
  CHECK(scene.mode == SimulationMode::Liquid);
  CHECK(scene.domain == glm::vec3(1.0f, 0.6f, 0.0f));
  CHECK_FALSE(scene.grid_resolution.has_value());
  CHECK(scene.gravity == glm::vec3(0.0f, -9.81f, 0.0f));
  CHECK(scene.density == 1000.0f);
  CHECK_FALSE(scene.rest_density.has_value());
  CHECK(scene.kernel_radius_cells == 3.0f);
  CHECK(scene.splat_format == SplatFormat::Auto);
  REQUIRE(scene.fluid_blocks.size() == 1);
  CHECK(scene.fluid_blocks[0].max == glm::vec3(0.3f, 0.45f, 0.0f));
  CHECK(scene.fluid_blocks[0].velocity == glm::vec3(0.0f));
  CHECK_FALSE(scene.camera.has_value());
}

TEST_CASE("given fields are read in physical units", "[scene]") {
  Json j = valid_3d();
  j["name"] = "tank";
  j["grid_resolution"] = 64;
  j["gravity"] = {0.0, -3.7, 0.0};
  j["rest_density"] = 998.5;
  j["stiffness"] = 120;
  j["gamma"] = 7;
  j["substeps"] = 64.0;  // an integral float is an integer
  j["splat_format"] = "rgba16f";
  j["fluid_blocks"][0]["velocity"] = {1.0, 0.0, -0.5};
  j["emitters"] = Json::array({{{"position", {0.5, 0.5, 0.25}},
                                {"velocity", {0.0, -1.0, 0.0}},
                                {"radius", 0.02},
                                {"start_time", 0.5},
                                {"stop_time", 2.0},
                                {"capacity", 1000}}});
  j["camera"] = {{"position", {0.5, 1.0, 2.0}}, {"target", {0.5, 0.2, 0.25}}};
  const Scene scene = parse(j);
  CHECK(scene.name == "tank");
  CHECK(scene.grid_resolution == 64);
  CHECK(scene.gravity == glm::vec3(0.0f, -3.7f, 0.0f));
  CHECK(scene.rest_density == 998.5f);
  CHECK(scene.stiffness == 120.0f);
  CHECK(scene.gamma == 7.0f);
  CHECK(scene.substeps == 64);
  CHECK(scene.splat_format == SplatFormat::Rgba16f);
  CHECK(scene.fluid_blocks[0].velocity == glm::vec3(1.0f, 0.0f, -0.5f));
  REQUIRE(scene.emitters.size() == 1);
  CHECK(scene.emitters[0].start_time == 0.5f);
  CHECK(scene.emitters[0].stop_time == 2.0f);
  CHECK(scene.emitters[0].capacity == 1000);
  REQUIRE(scene.camera.has_value());
  CHECK(scene.camera->fov_y_degrees == 45.0f);
  CHECK(scene.camera->target == glm::vec3(0.5f, 0.2f, 0.25f));
}

// The number keys' table (liquid/scene/number_keys.h) is the one place a plain number key is
// declared: this walks it, so a new row is checked without a test of its own.
TEST_CASE("every number key refuses values outside its range and reads one inside", "[scene]") {
  for (const scene_reader::NumberKey& row : scene_reader::number_keys()) {
    INFO(row.key);
    const bool integer = std::holds_alternative<int Scene::*>(row.member) ||
                         std::holds_alternative<std::optional<int> Scene::*>(row.member);
    const double below = integer ? row.lo - 1.0 : row.lo_open ? row.lo : row.lo - std::abs(row.lo) * 0.5 - 1e-3;
    const double above = integer ? row.hi + 1.0 : row.hi * 1.5 + 1e-3;
    for (const double outside : {below, above}) {
      Json j = valid_2d();
      j[row.key] = outside;
      REQUIRE_THROWS_WITH(parse(j), Contains(std::string("dam.json: ") + row.key + ": must be in"));
    }
    Json j = valid_2d();
    j[row.key] = "1";
    REQUIRE_THROWS_WITH(parse(j), Contains(std::string(row.key) + ": must be a"));
    // A value inside the range (the upper bound, the one a range is most often wrong about) is read.
    // The time step's upper bound is past the scene's stable step, so it takes its lower one.
    const bool step = std::string(row.key) == "time_step";
    const double inside = step ? row.lo : row.hi;
    j = valid_2d();
    j[row.key] = inside;
    if (std::string(row.key) == "kernel_radius_cells") j["particle_spacing"] = 0.002;  // below the kernel
    if (std::string(row.key) == "position_correction") j["splat"] = "separable";         // it reads its deposit
    if (std::string(row.key) == "projection_iterations") j["pressure_force"] = "splat_adjoint";
    const Scene scene = parse(j);
    std::visit(
        [&](auto member) {
          const auto& value = scene.*member;
          if constexpr (requires { value.value(); }) {
            REQUIRE(value.has_value());
            CHECK(double(*value) == Approx(inside));
          } else {
            CHECK(double(value) == Approx(inside));
          }
        },
        row.member);
    if (row.shallow_refusal) {
      Json shallow = valid_2d();
      shallow["mode"] = "shallow_water";
      shallow[row.key] = inside;
      REQUIRE_THROWS_WITH(parse(shallow), Contains(std::string(row.key) + ": " + row.shallow_refusal));
    }
  }
}

TEST_CASE("the README's scene table has a row for every top-level key", "[scene]") {
  std::ifstream file(std::filesystem::path(LIQUID_ASSET_DIR).parent_path() / "README.md");
  REQUIRE(file);
  std::stringstream text;
  text << file.rdbuf();
  // Every key the reader knows is refused when misspelled and documented when spelled right.
  Json probe = valid_2d();
  probe["no_such_key"] = 1;
  REQUIRE_THROWS_WITH(parse(probe), Contains("no_such_key: unknown key"));
  for (const char* key : scene_reader::top_level_keys()) {
    INFO(key);
    CHECK(text.str().find(std::string("| `") + key + "` |") != std::string::npos);
  }
}

TEST_CASE("the transfer is the chapter's unless the affine one is asked for with point sprites", "[scene]") {
  CHECK(parse(valid_2d()).transfer == Transfer::PicFlip);
  Json j = valid_2d();
  j["transfer"] = "affine";
  j["splat"] = "point_sprite";  // the default is the separable splat
  CHECK(parse(j).transfer == Transfer::Affine);
  refused_with("/transfer", "\"apic\"", "dam.json: transfer: must be one of \"pic_flip\", \"affine\", got \"apic\"");
  j["splat"] = "separable";
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: transfer: \"affine\" needs \"splat\": \"point_sprite\""));
  j = valid_2d();
  j["mode"] = "shallow_water";
  j["transfer"] = "pic_flip";
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: transfer: not used in shallow_water mode"));
}

TEST_CASE("the position correction is off unless asked for, and needs the separable splat", "[scene]") {
  CHECK(parse(valid_2d()).position_correction == 0.0f);
  Json j = valid_2d();
  j["splat"] = "separable";
  j["position_correction"] = 0.1;
  CHECK(parse(j).position_correction == Approx(0.1));
  j["splat"] = "point_sprite";
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: position_correction: needs \"splat\": \"separable\""));
  j.erase("splat");  // the default is the separable splat
  CHECK(parse(j).position_correction == Approx(0.1));
  j["position_correction"] = 0;
  CHECK(parse(j).position_correction == 0.0f);
  // Not yet with a dynamic body, which it floats too high.
  j["splat"] = "separable";
  j["pressure_force"] = "splat_adjoint";
  j["position_correction"] = 0.1;
  j["obstacles"] = Json::parse(R"([{"shape": "box", "center": [0.5, 0.5], "half_extent": [0.05, 0.05], "dynamic": true, "density": 500}])");
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: obstacles[0].dynamic: not yet with \"position_correction\""));
  j["position_correction"] = 0;
  CHECK(parse(j).obstacles.at(0).dynamic);
}

TEST_CASE("the pressure projection is the default, and needs the splat-adjoint pressure", "[scene]") {
  // Only the required keys: the shipped physical scenes' model.
  const Scene plain = parse(valid_2d());
  CHECK(plain.projection_iterations == k_default_projection_iterations);
  CHECK(plain.pressure_force == PressureForce::SplatAdjoint);
  CHECK(plain.splat == SplatMode::Separable);
  CHECK(plain.pic_ratio == 0.002f);
  CHECK(long_step_regime(plain));
  Json j = valid_2d();
  // Naming the chapter's pressure brings its own defaults for the keys left out.
  j["pressure_force"] = "chapter";
  CHECK(parse(j).projection_iterations == 0);
  CHECK(parse(j).pic_ratio == k_chapter_pic_ratio);
  CHECK_FALSE(long_step_regime(parse(j)));
  j["projection_iterations"] = 40;
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: projection_iterations: needs \"pressure_force\": \"splat_adjoint\""));
  j["pressure_force"] = "splat_adjoint";
  CHECK(parse(j).projection_iterations == 40);
  j["projection_iterations"] = 1;  // its first iteration reads the last step's solution, its last writes the next's
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: projection_iterations: must be 0 (no projection) or at least 2, got 1"));
  j["projection_iterations"] = 2;
  CHECK(parse(j).projection_iterations == 2);
  j["obstacles"] = Json::parse(R"([{"shape": "box", "center": [0.5, 0.5], "half_extent": [0.05, 0.05]}])");
  CHECK(parse(j).obstacles.size() == 1);  // a static obstacle is solid to the projection
  j["obstacles"][0]["dynamic"] = true;
  j["obstacles"][0]["density"] = 500;
  CHECK(parse(j).obstacles[0].dynamic);  // and a body too
}

TEST_CASE("whitewater is off unless asked for, and {} takes every default", "[scene][whitewater]") {
  CHECK_FALSE(parse(valid_2d()).whitewater.has_value());
  Json j = valid_3d();
  j["whitewater"] = Json::object();
  const Scene defaults = parse(j);
  REQUIRE(defaults.whitewater.has_value());
  CHECK(defaults.whitewater->slots_per_particle == Whitewater{}.slots_per_particle);
  CHECK(defaults.whitewater->lifetime == Whitewater{}.lifetime);
  j["whitewater"] = Json::parse(R"({"slots_per_particle": 3, "lifetime": 4.5, "crest_range": [5, 25],
                                    "spray_density": 0.1, "bubble_density": 0.9, "bubble_buoyancy": 1.5})");
  const Scene given = parse(j);
  CHECK(given.whitewater->slots_per_particle == 3);
  CHECK(given.whitewater->lifetime == 4.5f);
  CHECK(given.whitewater->crest_range == glm::vec2(5.0f, 25.0f));
  CHECK(given.whitewater->spray_density == 0.1f);
  CHECK(given.whitewater->bubble_density == 0.9f);
  CHECK(given.whitewater->bubble_buoyancy == 1.5f);
  CHECK(load_scene(k_scene_dir / "dam_break_3d_whitewater.json").whitewater.has_value());
}

TEST_CASE("bad whitewater settings are refused naming the key", "[scene][whitewater]") {
  refused_with("/whitewater", "true", "dam.json: whitewater: must be an object, got boolean");
  refused_with("/whitewater", R"({"foam": 1})", "dam.json: whitewater.foam: unknown key");
  refused_with("/whitewater", R"({"slots_per_particle": 0})", "dam.json: whitewater.slots_per_particle: must be in [1, 8], got 0");
  refused_with("/whitewater", R"({"slots_per_particle": 1.5})", "whitewater.slots_per_particle: must be an integer");
  refused_with("/whitewater", R"({"lifetime": 0})", "dam.json: whitewater.lifetime: must be in (0, 1000], got 0");
  refused_with("/whitewater", R"({"crest_range": [20, 10]})",
               "dam.json: whitewater.crest_range: must be [lo, hi] with 0 <= lo < hi, got [20, 10]");
  refused_with("/whitewater", R"({"speed_range": [1]})", "dam.json: whitewater.speed_range: must have 2 components");
  refused_with("/whitewater", R"({"spray_density": 0.8, "bubble_density": 0.5})",
               "dam.json: whitewater.bubble_density: must be greater than spray_density (0.8), got 0.5");
  refused_with("/whitewater", R"({"bubble_drag": -1})", "dam.json: whitewater.bubble_drag: must be in [0, 1000], got -1");
  Json shallow = Json::parse(R"({"dimension": 2, "mode": "shallow_water", "domain": [1, 1], "particle_spacing": 0.01,
                                 "fluid_blocks": [{"min": [0, 0], "max": [0.5, 0.5]}], "whitewater": {}})");
  REQUIRE_THROWS_WITH(parse(shallow), Contains("whitewater: not available in shallow_water mode"));
}

TEST_CASE("rest_density \"auto\" leaves it to the setup", "[scene]") {
  Json j = valid_2d();
  j["rest_density"] = "auto";
  CHECK_FALSE(parse(j).rest_density.has_value());
}

TEST_CASE("obstacles are read per shape, metaballs relative to their centroid", "[scene]") {
  Json j = valid_2d();
  j["obstacles"] = Json::parse(R"([
    { "shape": "sphere", "center": [0.5, 0.2], "radius": 0.1, "velocity": [0.1, 0.0] },
    { "shape": "box", "center": [0.7, 0.2], "half_extent": [0.05, 0.1],
      "oscillation": { "amplitude": [0.0, 0.05], "frequency": 2 } },
    { "shape": "metaballs", "balls": [ { "center": [0.4, 0.1], "radius": 0.05 },
                                       { "center": [0.6, 0.3], "radius": 0.07 } ], "threshold": 0.3 }
  ])");
  const Scene scene = parse(j);
  REQUIRE(scene.obstacles.size() == 3);
  CHECK(scene.obstacles[0].radius == 0.1f);
  CHECK(scene.obstacles[0].velocity == glm::vec3(0.1f, 0.0f, 0.0f));
  CHECK(scene.obstacles[1].half_extent == glm::vec3(0.05f, 0.1f, 0.0f));
  CHECK(scene.obstacles[1].oscillation_amplitude == glm::vec3(0.0f, 0.05f, 0.0f));
  CHECK(scene.obstacles[1].oscillation_frequency == 2.0f);
  const Obstacle& blob = scene.obstacles[2];
  CHECK(blob.threshold == 0.3f);
  CHECK(blob.center.x == Approx(0.5f));
  CHECK(blob.center.y == Approx(0.2f));
  REQUIRE(blob.balls.size() == 2);
  CHECK(blob.balls[0].center.x == Approx(-0.1f));
  CHECK(blob.balls[1].center.y == Approx(0.1f));
  CHECK(blob.balls[1].radius == 0.07f);
}

TEST_CASE("shallow water reads its rest depth and ground", "[scene]") {
  Json j = valid_2d();
  j["mode"] = "shallow_water";
  j["rest_depth"] = 0.05;
  j["ground"] = Json::parse(R"([{ "center": [0.5, 0.3], "height": 0.02, "width": 0.1 }])");
  const Scene scene = parse(j);
  CHECK(scene.mode == SimulationMode::ShallowWater);
  CHECK(scene.rest_depth == 0.05f);
  REQUIRE(scene.ground.size() == 1);
  CHECK(scene.ground[0].center == glm::vec2(0.5f, 0.3f));
}

TEST_CASE("malformed scenes are rejected naming the file and field", "[scene]") {
  SECTION("unknown key at the top level") {
    refused_with("/stiffnes", "50", "dam.json: stiffnes: unknown key");
  }
  SECTION("unknown key in a nested object") {
    refused_with("/fluid_blocks/0/veloctiy", "[1.0, 0.0]", "dam.json: fluid_blocks[0].veloctiy: unknown key");
  }
  SECTION("a key of another obstacle shape") {
    refused_with("/obstacles", R"([{ "shape": "sphere", "center": [0.5, 0.2], "radius": 0.1,
                                        "half_extent": [0.1, 0.1] }])",
                 "dam.json: obstacles[0].half_extent: unknown key");
  }
  SECTION("wrong type") {
    refused_with("/gamma", R"("5")", "dam.json: gamma: must be a number, got string");
  }
  SECTION("wrong type inside a vector") {
    refused_with("/gravity", R"([0.0, "down"])", "dam.json: gravity[1]: must be a number, got string");
  }
  SECTION("gamma out of range") {
    refused_with("/gamma", "12", "dam.json: gamma: must be in [1, 10], got 12");
  }
  SECTION("negative particle spacing") {
    Json j = valid_2d();
    j["particle_spacing"] = -0.01;
    REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: particle_spacing: must be in (0, 0.3]") && Contains("got -0.01"));
  }
  SECTION("fluid block outside the domain") {
    refused_with("/fluid_blocks/0/max", "[0.3, 0.7]",
                 "dam.json: fluid_blocks[0].max: must be inside the domain [0, 1] x [0, 0.6]");
  }
  SECTION("fluid block with min >= max") {
    refused_with("/fluid_blocks/0/min", "[0.3, 0.0]", "dam.json: fluid_blocks[0].max: must be greater than min");
  }
  SECTION("vector of the wrong length") {
    refused_with("/domain", "[1.0, 0.6, 0.5]", "dam.json: domain: must have 2 components, got 3");
  }
  SECTION("missing dimension") {
    Json j = valid_2d();
    j.erase("dimension");
    REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: dimension: missing required key"));
  }
  SECTION("dimension other than 2 or 3") {
    refused_with("/dimension", "4", "dam.json: dimension: must be in [2, 3], got 4");
  }
  SECTION("malformed JSON") {
    const std::string text = "{\n  \"dimension\": 2,\n  \"domain\": [1.0, 0.6,\n}\n";
    REQUIRE_THROWS_WITH(parse_scene(text, "dam.json"), Contains("dam.json: line 4: JSON syntax error"));
  }
  SECTION("number too large for a double") {
    REQUIRE_THROWS_WITH(parse_scene(R"({"dimension": 2, "gamma": 1e999})", "dam.json"),
                        Contains("dam.json: JSON error: number overflow"));
  }
  SECTION("duplicate key") {
    const std::string text = R"({"dimension": 2, "fluid_blocks": [{"min": [0, 0], "max": [1, 1], "min": [0, 0]}]})";
    REQUIRE_THROWS_WITH(parse_scene(text, "dam.json"), Contains("dam.json: fluid_blocks[0].min: duplicate key"));
  }
  SECTION("document is not an object") {
    REQUIRE_THROWS_WITH(parse_scene("[1, 2]", "dam.json"), Contains("dam.json: (document): must be a JSON object"));
  }
  SECTION("shallow water in 3D") {
    Json j = valid_3d();
    j["mode"] = "shallow_water";
    REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: mode: shallow_water requires dimension 2, got 3"));
  }
  SECTION("unknown mode") {
    refused_with("/mode", R"("lava")", "dam.json: mode: must be one of \"liquid\", \"shallow_water\"");
  }
  SECTION("stiffness in shallow water") {
    Json j = valid_2d();
    j["mode"] = "shallow_water";
    j["stiffness"] = 10;
    REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: stiffness: not used in shallow_water mode"));
  }
  SECTION("ground in liquid mode") {
    refused_with("/ground", R"([{ "center": [0.5, 0.3], "height": 0.02, "width": 0.1 }])",
                 "dam.json: ground: only allowed in shallow_water mode");
  }
  SECTION("emitter with zero velocity") {
    refused_with("/emitters", R"([{ "position": [0.5, 0.5], "velocity": [0, 0], "radius": 0.02,
                                       "capacity": 100 }])",
                 "dam.json: emitters[0].velocity: must be nonzero");
  }
  SECTION("emitter stopping before it starts") {
    refused_with("/emitters", R"([{ "position": [0.5, 0.5], "velocity": [1, 0], "radius": 0.02,
                                       "start_time": 1.0, "stop_time": 0.5, "capacity": 100 }])",
                 "dam.json: emitters[0].stop_time: must be greater than start_time");
  }
  SECTION("emitter capacity that is not an integer") {
    refused_with("/emitters", R"([{ "position": [0.5, 0.5], "velocity": [1, 0], "radius": 0.02,
                                       "capacity": 10.5 }])",
                 "dam.json: emitters[0].capacity: must be an integer, got 10.5");
  }
  SECTION("camera in 2D") {
    refused_with("/camera", R"({ "position": [0.5, 1.0, 2.0], "target": [0.5, 0.2, 0.25] })",
                 "dam.json: camera: only allowed in 3D scenes");
  }
  SECTION("metaballs threshold outside (0, 1)") {
    refused_with("/obstacles", R"([{ "shape": "metaballs", "balls": [{ "center": [0.5, 0.2], "radius": 0.1 }],
                                        "threshold": 1 }])",
                 "dam.json: obstacles[0].threshold: must be in (0, 1), got 1");
  }
  SECTION("rest density that is neither a number nor auto") {
    refused_with("/rest_density", R"("automatic")", "dam.json: rest_density: must be a number or \"auto\"");
  }
  SECTION("no fluid block and no emitter") {
    Json j = valid_2d();
    j.erase("fluid_blocks");
    REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: fluid_blocks: the scene needs at least one fluid block"));
  }
  SECTION("missing file") {
    const std::filesystem::path missing = k_scene_dir / "no_such_scene.json";
    REQUIRE_THROWS_WITH(load_scene(missing), Contains(missing.string() + ": cannot open scene file"));
  }
  SECTION("every error is a SceneError") {
    Json j = valid_2d();
    j["time_step"] = 1.0;
    REQUIRE_THROWS_AS(parse(j), SceneError);
  }
}

TEST_CASE("a key with a newline or of a megabyte is named on one short line", "[scene]") {
  Json j = valid_2d();
  j["bad\nkey"] = 1;
  REQUIRE_THROWS_WITH(parse(j), Contains("dam.json: bad\\nkey: unknown key"));
  Json big = valid_2d();
  big[std::string(1 << 20, 'k')] = 1;
  try {
    parse(big);
    FAIL("a megabyte key was accepted");
  } catch (const SceneError& error) {
    const std::string message = error.what();
    CHECK(message.size() < 200);
    CHECK(message.find("(1048576 bytes)") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
}
