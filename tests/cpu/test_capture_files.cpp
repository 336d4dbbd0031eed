// The CPU side of the capture tool's caches: per-particle density sampled from the grid, the foam
// splatted onto it, and scene fields overridden the way --set does it, checked like the file.
#include "liquid/export/volume.h"
#include "liquid/types.h"
#include "liquid/scene.h"
#include "liquid/scene/override.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

namespace {

std::filesystem::path scene_file(const std::string& text) {
  const std::filesystem::path folder = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / "scene_override";
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / "pool.json";
  std::ofstream(path) << text;
  return path;
}

const char* k_pool = R"({ "dimension": 2, "domain": [1, 0.5], "particle_spacing": 0.02,
  "fluid_blocks": [ { "min": [0, 0], "max": [0.5, 0.2] } ] })";

}  // namespace

TEST_CASE("per-particle density is the grid interpolated between cell centres", "[export]") {
  liquid::VolumeFrame v;
  v.cells = {4, 2, 1};
  v.cell_size = 0.5f;
  v.density = {0, 1, 2, 3, 4, 5, 6, 7};  // rho = x index + 4 * y index
  v.velocity.resize(8);
  const std::vector<float> rho = liquid::sample_density(
      v, {{0.25f, 0.25f, 0, 1}, {0.5f, 0.25f, 0, 1}, {0.75f, 0.5f, 0, 1}, {-3.0f, 9.0f, 0, 1}, {1.75f, 0.75f, 0, 1}});
  CHECK(rho[0] == Approx(0.0f));  // a cell centre
  CHECK(rho[1] == Approx(0.5f));  // halfway between two centres
  CHECK(rho[2] == Approx(3.0f));  // (1 + 5) / 2
  CHECK(rho[3] == Approx(4.0f));  // outside: clamped to the nearest centre (0, 1)
  CHECK(rho[4] == Approx(7.0f));  // the last cell's centre
}

TEST_CASE("a surface vertex's velocity is the grid's over the cells that hold liquid", "[export]") {
  liquid::VolumeFrame v;
  v.cells = {2, 2, 2};
  v.cell_size = 1.0f;
  v.density.assign(8, 0.0f);
  v.velocity.assign(8, glm::vec4(0.0f));       // air: no liquid, no velocity
  v.velocity[0] = glm::vec4(1, 0, 0, 1);       // the liquid: cells (0, 0, 0) and (1, 0, 0)
  v.velocity[1] = glm::vec4(3, 0, 0, 1);
  const std::vector<glm::vec3> u = liquid::sample_velocity(v, {{0.75f, 1.0f, 1.0f}, {1.0f, 0.5f, 0.5f}, {1.5f, 0.75f, 0.75f}});
  CHECK(u[0].x == Approx(1.5f));  // a quarter of the way from (0, 0, 0)'s centre to (1, 0, 0)'s; the air left out
  CHECK(u[1].x == Approx(2.0f));
  CHECK(u[2].x == Approx(3.0f));  // air and (1, 0, 0) in the stencil
  CHECK(liquid::sample_velocity(v, {{0.5f, 1.5f, 1.5f}})[0] == glm::vec3(0.0f));  // no liquid: zero
}

TEST_CASE("the foam grid spreads each foam particle over its cells' centres and integrates to their count", "[export]") {
  liquid::VolumeFrame v;
  v.cells = {4, 3, 2};
  v.cell_size = 0.5f;
  const auto particle = [](glm::vec3 p, liquid::WhitewaterKind kind) {
    liquid::WhitewaterParticle w;
    w.position = p;
    w.kind = kind;
    return w;
  };
  using liquid::WhitewaterKind;
  const std::vector<float> foam = liquid::foam_number_density(
      v, {particle({0.25f, 0.25f, 0.25f}, WhitewaterKind::Foam),     // cell (0, 0, 0)'s centre
          particle({1.0f, 0.75f, 0.25f}, WhitewaterKind::Foam),      // halfway between (1, 1, 0) and (2, 1, 0)
          particle({1.9f, 1.4f, 0.9f}, WhitewaterKind::Foam),        // past the last centres: clamped to (3, 2, 1)
          particle({0.25f, 0.25f, 0.25f}, WhitewaterKind::Spray),    // not foam: left out
          particle({0.75f, 0.25f, 0.25f}, WhitewaterKind::Bubble)});
  REQUIRE(foam.size() == 24);
  const float per_m3 = 1.0f / (0.5f * 0.5f * 0.5f);
  CHECK(foam[v.index(0, 0, 0)] == Approx(per_m3));
  CHECK(foam[v.index(1, 0, 0)] == 0.0f);  // the bubble's cell: nothing
  CHECK(foam[v.index(1, 1, 0)] == Approx(0.5f * per_m3));
  CHECK(foam[v.index(2, 1, 0)] == Approx(0.5f * per_m3));
  CHECK(foam[v.index(3, 2, 1)] == Approx(per_m3));
  double count = 0.0;
  for (float n : foam) count += n * 0.5 * 0.5 * 0.5;
  CHECK(count == Approx(3.0));
  // 2D: bilinear over the one-cell-deep grid, still per m^3 of its cells.
  v.cells = {4, 3, 1};
  const std::vector<float> flat = liquid::foam_number_density(v, {particle({0.5f, 0.25f, 0.0f}, WhitewaterKind::Foam)});
  CHECK(flat[v.index(0, 0, 0)] == Approx(0.5f * per_m3));
  CHECK(flat[v.index(1, 0, 0)] == Approx(0.5f * per_m3));
}

TEST_CASE("scene overrides (the capture tool's --set) are applied to the document and checked like the file", "[scene]") {
  const std::filesystem::path path = scene_file(k_pool);
  using liquid::SceneOverride;
  const auto scene_with = [&](std::vector<SceneOverride> overrides) {
    return liquid::parse_scene(liquid::scene_document(path, overrides), "pool.json with --set");
  };
  const liquid::Scene s = scene_with({{"stiffness", "20"}, {"fluid_blocks[0].max", "[0.3, 0.1]"},
                                      {"fluid_blocks.0.velocity", "[1, 0]"}, {"splat_format", "rgba16f"}});
  CHECK(s.name == "pool");  // the file's stem, as without --set
  CHECK(s.stiffness == 20.0f);
  CHECK(s.fluid_blocks[0].max.x == 0.3f);
  CHECK(s.fluid_blocks[0].velocity.x == 1.0f);
  CHECK(s.splat_format == liquid::SplatFormat::Rgba16f);

  CHECK_THROWS_WITH(scene_with({{"stiffness", "-1"}}), Catch::Contains("pool.json with --set: stiffness: must be"));
  CHECK_THROWS_WITH(scene_with({{"stifness", "1"}}), Catch::Contains("stifness: unknown key"));
  CHECK_THROWS_WITH(scene_with({{"fluid_blocks.1.min", "[0, 0]"}}), Catch::Contains("fluid_blocks has 1 element"));
  CHECK_THROWS_WITH(scene_with({{"dimension.x", "1"}}), Catch::Contains("dimension is a number, it has no field 'x'"));
  CHECK_THROWS_WITH(scene_with({{"fluid_blocks.first", "1"}}), Catch::Contains("expected an index"));
  CHECK_THROWS_WITH(scene_with({{"a..b", "1"}}), Catch::Contains("not a field path"));
  CHECK_THROWS_AS(liquid::parse_scene_override("=3"), liquid::ArgumentError);
  // A path naming no field is a bad flag, refused before any scene is read.
  for (const char* text : {"a..b=1", "a.=1", ".a=1"})
    CHECK_THROWS_MATCHES(liquid::parse_scene_override(text), liquid::ArgumentError,
                         Catch::Message(std::string("--set ") + std::string(text).substr(0, std::string(text).find('=')) +
                                        ": not a field path (use name, camera.position, fluid_blocks.0.max)"));
  CHECK(liquid::parse_scene_override("camera.position=[1,2,3]").value == "[1,2,3]");

  // Limits apply to the override itself, before its value is parsed or the document printed again
  // (60,000 nested brackets once took 104 s and 7.9 GB to pretty-print).
  const std::string deep_value = std::string(200000, '[') + std::string(200000, ']');
  const std::string nested_limit = "the path and its value nest deeper than the 8 levels a scene may";
  CHECK_THROWS_WITH(scene_with({{"x", deep_value}}), Catch::Equals("--set x: " + nested_limit));
  CHECK_THROWS_WITH(scene_with({{"x", "[[[[[[[[1]]]]]]]]"}}), Catch::Equals("--set x: " + nested_limit));  // 1 + 8
  std::string deep_path = "a";
  for (int i = 0; i < 100000; ++i) deep_path += ".a";
  CHECK_THROWS_WITH(scene_with({{deep_path, "1"}}), Catch::EndsWith(nested_limit));
  CHECK_THROWS_WITH(scene_with({{"name", '"' + std::string(5 << 20, 'x') + '"'}}),
                    Catch::Equals("--set name: the value is 5242882 bytes, larger than the 4 MiB a scene may be"));
  CHECK_NOTHROW(scene_with({{"obstacles", R"([{"shape": "metaballs", "balls": [{"center": [0.2, 0.1], "radius": 0.02}]}])"}}));
  // User text in a message stays on one line, and a long one is cut.
  CHECK_THROWS_WITH(scene_with({{"fluid_blocks.fi\nrst", "1"}}), !Catch::Contains("\n"));
  CHECK_THROWS_WITH(scene_with({{"fluid_blocks." + std::string(10000, 'k'), "1"}}),
                    Catch::Contains("got 'kkkkkkkk") && Catch::EndsWith("... (10000 bytes)'"));

  // The file is checked on its own first: its errors keep naming the file.
  const std::filesystem::path bad = scene_file(R"({ "dimension": 4 })");
  CHECK_THROWS_WITH(liquid::scene_document(bad, {{"dimension", "2"}}), Catch::Contains("pool.json: dimension"));
}
