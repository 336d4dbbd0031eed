// Output files: binary PLY particles and the temp-then-rename writer every tool uses.
#include "engine/io/atomic_file.h"
#include "liquid/export/ply.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

std::filesystem::path scratch_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

std::string read_all(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("PLY export writes a little-endian header, the frame's time and eight values per particle", "[export]") {
  liquid::ParticleSnapshot particles;
  particles.positions = {{0.1f, 0.2f, 0.3f, 1.0f}, {1.5f, -2.0f, 0.0f, 1.0f}};
  particles.velocities = {{4.0f, 5.0f, 6.0f, 0.0f}, {-1.0f, 0.25f, 8.0f, 0.0f}};
  const std::string ply = liquid::encode_ply(particles, liquid::PlyFrame{12, 0.1, {1.0f, 0.625f}});
  const std::string end = "end_header\n";
  const size_t body = ply.find(end);
  REQUIRE(body != std::string::npos);
  const std::string header = ply.substr(0, body + end.size());
  CHECK(header.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  CHECK(header.find("element vertex 2\n") != std::string::npos);
  CHECK(header.find("comment frame 12\n") != std::string::npos);
  CHECK(header.find("comment time_s 0.10000000000000001\n") != std::string::npos);  // the double, exactly
  for (const char* p : {"x", "y", "z", "vx", "vy", "vz", "density"})
    CHECK(header.find(std::string("property float ") + p + "\n") != std::string::npos);
  CHECK(header.find("property int id\n") != std::string::npos);
  constexpr size_t k_vertex = 8 * 4;
  REQUIRE(ply.size() == header.size() + 2 * k_vertex);
  float second[6];
  int32_t id = -1;
  float density = 0.0f;
  const char* vertex = ply.data() + header.size() + k_vertex;
  std::memcpy(second, vertex, sizeof second);
  std::memcpy(&id, vertex + 24, 4);
  std::memcpy(&density, vertex + 28, 4);
  CHECK(second[0] == 1.5f);
  CHECK(second[1] == -2.0f);
  CHECK(second[3] == -1.0f);
  CHECK(second[5] == 8.0f);
  CHECK(id == 1);  // the particle's index: stable across frames
  CHECK(density == 0.625f);

  CHECK_THROWS_AS(liquid::encode_ply(particles, liquid::PlyFrame{0, 0.0, {1.0f}}), liquid::ArgumentError);
  particles.velocities.pop_back();
  CHECK_THROWS_AS(liquid::encode_ply(particles, liquid::PlyFrame{0, 0.0, {1.0f, 1.0f}}), liquid::ArgumentError);
}

TEST_CASE("atomic writes replace the file whole and leave nothing behind on failure", "[export]") {
  const std::filesystem::path folder = scratch_folder("atomic_file");
  const std::filesystem::path path = folder / "stats.csv";
  engine::io::write_file_atomically(path, "first\n");
  engine::io::write_file_atomically(path, "second version\n");
  CHECK(read_all(path) == "second version\n");
  CHECK_FALSE(std::filesystem::exists(folder / "stats.csv.partial"));

  const std::filesystem::path missing = folder / "no_such_folder" / "frame.png";
  CHECK_THROWS_WITH(engine::io::write_file_atomically(missing, "x"), Catch::Contains("no_such_folder"));
  CHECK_FALSE(std::filesystem::exists(missing));
  CHECK_FALSE(std::filesystem::exists(folder / "no_such_folder"));

  CHECK_NOTHROW(engine::io::ensure_writable_folder(folder / "new" / "nested"));
  CHECK(std::filesystem::is_directory(folder / "new" / "nested"));
  CHECK_THROWS_WITH(engine::io::ensure_writable_folder("/proc/liquid_out"), Catch::Contains("/proc/liquid_out"));
}
