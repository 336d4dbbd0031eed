// Scene files that are large, deep or odd: each loads or is refused, in one line naming the file
// (and the field), within a stated time. The loader used to be quadratic in the number of objects
// (200,000 empty objects in one array took 4.8 s; a 50 MB file was read whole and took 11 s and
// 1.2 GB before being refused), so the timings here are the finding's test.
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

using namespace liquid;
using Catch::Contains;
using Catch::StartsWith;

namespace {

// Wall time of `f` in seconds.
template <typename F>
double seconds_of(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The message `text` is refused with, and how long that took (fails if it loads).
std::pair<std::string, double> refusal(const std::string& text) {
  std::string message;
  const double seconds = seconds_of([&] {
    try {
      parse_scene(text, "big.json");
    } catch (const SceneError& e) {
      message = e.what();
    }
  });
  return {message, seconds};
}

// "[{}, {}, ...]" with `count` empty objects.
std::string empty_objects(int count) {
  std::string text = "[";
  for (int i = 0; i < count; ++i) text += i ? ",{}" : "{}";
  return text + "]";
}

// A 3D scene of `count` fluid blocks: 8 mm cubes on a 64 x 64 x n lattice of 1 cm.
std::string scene_with_blocks(int count) {
  std::string text = R"({"dimension": 3, "domain": [1, 1, 1], "particle_spacing": 0.004, "fluid_blocks": [)";
  for (int i = 0; i < count; ++i) {
    const double x = 0.01 * (i % 64), y = 0.01 * ((i / 64) % 64), z = 0.01 * (i / 4096);
    text += std::string(i ? "," : "") + "\n  {\"min\": [" + std::to_string(x) + ", " + std::to_string(y) + ", " +
            std::to_string(z) + "], \"max\": [" + std::to_string(x + 0.008) + ", " + std::to_string(y + 0.008) + ", " +
            std::to_string(z + 0.008) + "], \"velocity\": [0, -1, 0]}";
  }
  return text + "]}";
}

// Both bounds hold with a wide margin on a 2-core CI machine, under AddressSanitizer too.
constexpr double k_load_seconds = 2.0;

}  // namespace

TEST_CASE("a scene with the most fluid blocks allowed loads in linear time", "[scene][limits]") {
  const std::string text = scene_with_blocks(k_max_fluid_blocks);
  Scene scene;
  const double seconds = seconds_of([&] { scene = parse_scene(text, "many_blocks.json"); });
  INFO(text.size() << " bytes in " << seconds << " s");
  CHECK(scene.fluid_blocks.size() == size_t(k_max_fluid_blocks));
  CHECK(seconds < k_load_seconds);
  // One more is refused by name.
  const auto [message, refused_in] = refusal(scene_with_blocks(k_max_fluid_blocks + 1));
  CHECK_THAT(message, StartsWith("big.json: fluid_blocks: has more than 16384 elements"));
  CHECK(refused_in < k_load_seconds);
}

TEST_CASE("large or deep scene files are refused quickly, naming the limit", "[scene][limits]") {
  SECTION("200,000 empty objects in one list") {
    const auto [message, seconds] = refusal(R"({"dimension": 2, "junk": )" + empty_objects(200000) + "}");
    CHECK_THAT(message, StartsWith("big.json: junk: has more than 16384 elements"));
    CHECK(seconds < k_load_seconds);
  }
  SECTION("4 MiB of empty objects in lists of lists") {
    std::string inner = empty_objects(16000);
    std::string text = R"({"junk": [)";
    while (text.size() + inner.size() + 2 < k_max_scene_bytes) text += inner + ",";
    text.back() = ']';
    text += "}";
    const auto [message, seconds] = refusal(text);
    CHECK_THAT(message, StartsWith("big.json: junk[") && Contains("more than 524288 JSON values"));
    CHECK(seconds < k_load_seconds);
  }
  SECTION("a file past the size limit") {
    const auto [message, seconds] = refusal(std::string(k_max_scene_bytes + 1, ' '));
    CHECK_THAT(message, StartsWith("big.json: 4194305 bytes, larger than the 4 MiB a scene file may be"));
    CHECK(seconds < k_load_seconds);
  }
  SECTION("nesting past the limit") {
    const auto [message, seconds] = refusal(std::string(100000, '[') + std::string(100000, ']'));
    CHECK_THAT(message, StartsWith("big.json: [0][0][0][0][0][0][0][0]: nested deeper than 8 levels"));
    CHECK(seconds < k_load_seconds);
  }
  SECTION("the deepest real scene nesting is allowed") {
    const Scene scene = parse_scene(R"({"dimension": 2, "domain": [1, 1], "particle_spacing": 0.01,
        "fluid_blocks": [{"min": [0, 0], "max": [0.2, 0.2]}],
        "obstacles": [{"shape": "metaballs", "balls": [{"center": [0.5, 0.5], "radius": 0.1}]}]})",
                                    "deep.json");
    CHECK(scene.obstacles.at(0).balls.size() == 1);
  }
}

TEST_CASE("a 50 MB scene file is refused without being read whole", "[scene][limits]") {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "liquid_test_50mb_scene.json";
  {
    std::ofstream file(path, std::ios::binary);
    file << R"({"dimension": 2, "junk": [)";
    const std::string chunk(1 << 20, '0');
    for (int i = 0; i < 50; ++i) file << chunk;
    file << "]}";
  }
  std::string message;
  const double seconds = seconds_of([&] {
    try {
      load_scene(path);
    } catch (const SceneError& e) {
      message = e.what();
    }
  });
  std::filesystem::remove(path);
  CHECK_THAT(message, StartsWith(path.string() + ": larger than the 4 MiB a scene file may be"));
  CHECK(seconds < 1.0);
}

TEST_CASE("a folder or a device given as the scene is named as such", "[scene][limits]") {
  REQUIRE_THROWS_WITH(load_scene(test_scenes::k_scene_dir),
                      test_scenes::k_scene_dir.string() + ": is a directory, not a scene file");
  // An endless file is cut at the size limit rather than read until memory runs out.
  REQUIRE_THROWS_WITH(load_scene("/dev/zero"), "/dev/zero: larger than the 4 MiB a scene file may be");
  REQUIRE_THROWS_WITH(load_scene(test_scenes::k_scene_dir / "no_such_scene.json"),
                      Contains("no_such_scene.json: cannot open scene file (No such file or directory)"));
}

TEST_CASE("the solver's list limits hold for a scene file and for a scene built in code", "[scene][limits]") {
  // From a file: the reader refuses the ninth obstacle, naming the file and the list.
  const std::string sphere = R"({"shape": "sphere", "center": [0.8, 0.1], "radius": 0.01})";
  std::string obstacles = sphere;
  for (int i = 1; i < 9; ++i) obstacles += ", " + sphere;
  const std::string text = R"({"dimension": 2, "domain": [1.0, 0.6], "particle_spacing": 0.01,
    "fluid_blocks": [{"min": [0.0, 0.0], "max": [0.3, 0.45]}], "obstacles": [)" + obstacles + "]}";
  REQUIRE_THROWS_WITH(parse_scene(text, "nine.json"), "nine.json: obstacles: at most 8 are supported, got 9");
  // Built in code, past the reader: make_setup refuses it before any stage indexes the solver's
  // fixed-size arrays (obstacles, metaballs, ground hills, emitters).
  Scene scene = test_scenes::scene_of("obstacles_2d.json");
  scene.source.clear();
  scene.name = "code";
  const auto refused = [](const Scene& s, const std::string& message) {
    REQUIRE_THROWS_AS(make_setup(s, {}), SceneError);
    REQUIRE_THROWS_WITH(make_setup(s, {}), message);
  };
  Scene many = scene;
  many.obstacles.resize(9, scene.obstacles.front());
  refused(many, "code: obstacles: at most 8 are supported, got 9");
  Scene balls = scene;
  balls.obstacles.resize(1);
  balls.obstacles[0].shape = ObstacleShape::Metaballs;
  balls.obstacles[0].balls.resize(33);
  refused(balls, "code: obstacles: at most 32 metaballs in all are supported, got 33");
  Scene emitters = scene;
  emitters.emitters.resize(5);
  refused(emitters, "code: emitters: at most 4 are supported, got 5");
  Scene hills = scene;
  hills.ground.resize(17);
  refused(hills, "code: ground: at most 16 are supported, got 17");
}
