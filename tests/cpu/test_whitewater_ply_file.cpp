// The whitewater's PLY file: written to disk, then read back as a reader does it, from the header's
// element and property lines alone (tests/support/ply_points.h): the type names in comments, the
// frame and its time, each property's type, and every value as it was.
#include "liquid/export/whitewater_ply.h"
#include "tests/support/ply_points.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>

namespace {

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / "whitewater_ply";
  std::filesystem::create_directories(folder);
  return folder / name;
}

}  // namespace

TEST_CASE("the whitewater PLY names its types in comments and reads back every value it was given", "[export]") {
  std::vector<liquid::WhitewaterParticle> particles(3);
  particles[0] = {{0.1f, 0.2f, 0.3f}, {1.0f, -2.0f, 0.5f}, liquid::WhitewaterKind::Spray, 0.25f, (uint64_t(7) << 32) | 0x3f800000u};
  particles[1] = {{0.4f, 0.05f, 0.2f}, {0.0f, 0.0f, -0.125f}, liquid::WhitewaterKind::Foam, 1.5f, (uint64_t(123456) << 32) | 1u};
  particles[2] = {{0.9f, 0.01f, 0.0f}, {-3.0f, 4.0f, 0.0f}, liquid::WhitewaterKind::Bubble, 0.0f, 0xfffffffeull << 32};
  const std::filesystem::path path = scratch("whitewater_00012.ply");
  liquid::write_whitewater_ply(path, particles, liquid::WhitewaterPlyFrame{12, 0.1, 30.0});
  CHECK_FALSE(std::filesystem::exists(path.string() + ".partial"));

  const test::PlyPoints ply = test::read_ply_points(path);
  CHECK(ply.format == "binary_little_endian 1.0");
  for (const char* comment : {"type 1 spray", "type 2 foam", "type 3 bubble", "frame 12", "time_s 0.10000000000000001",
                              "fps 30"})
    CHECK(std::find(ply.comments.begin(), ply.comments.end(), comment) != ply.comments.end());
  CHECK(ply.properties == std::vector<std::pair<std::string, std::string>>{
                              {"float", "x"},     {"float", "y"},   {"float", "z"},    {"float", "vx"},
                              {"float", "vy"},    {"float", "vz"},  {"uchar", "type"}, {"float", "age"},
                              {"uint", "id_hi"},  {"uint", "id_lo"}});
  REQUIRE(ply.vertices.size() == particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    INFO("particle " << i);
    const liquid::WhitewaterParticle& p = particles[i];
    std::map<std::string, double> values = ply.vertices[i];
    CHECK(float(values["x"]) == p.position.x);
    CHECK(float(values["y"]) == p.position.y);
    CHECK(float(values["z"]) == p.position.z);
    CHECK(float(values["vx"]) == p.velocity.x);
    CHECK(float(values["vy"]) == p.velocity.y);
    CHECK(float(values["vz"]) == p.velocity.z);
    CHECK(values["type"] == double(p.kind));
    CHECK(float(values["age"]) == p.age);
    CHECK(((uint64_t(values["id_hi"]) << 32) | uint64_t(values["id_lo"])) == p.id);
  }
}

TEST_CASE("a frame with no live secondary particles is a whole PLY of 0 vertices", "[export]") {
  const std::filesystem::path path = scratch("whitewater_00000.ply");
  liquid::write_whitewater_ply(path, {}, liquid::WhitewaterPlyFrame{0, 0.0, 0.0});
  const test::PlyPoints ply = test::read_ply_points(path);  // throws if bytes follow the header
  CHECK(ply.vertices.empty());
  CHECK(ply.properties.size() == 10);
  CHECK(std::find(ply.comments.begin(), ply.comments.end(), "type 2 foam") != ply.comments.end());
  CHECK(std::none_of(ply.comments.begin(), ply.comments.end(), [](const std::string& c) { return c.rfind("fps", 0) == 0; }));
}
