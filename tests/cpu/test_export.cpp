// Output files: binary PLY particles and the temp-then-rename writer every tool uses.
#include "engine/io/atomic_file.h"
#include "liquid/export/ply.h"

#include <catch2/catch.hpp>

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

TEST_CASE("PLY export writes a little-endian header and six floats per particle", "[export]") {
  liquid::ParticleSnapshot particles;
  particles.positions = {{0.1f, 0.2f, 0.3f, 1.0f}, {1.5f, -2.0f, 0.0f, 1.0f}};
  particles.velocities = {{4.0f, 5.0f, 6.0f, 0.0f}, {-1.0f, 0.25f, 8.0f, 0.0f}};
  const std::string ply = liquid::encode_ply(particles);
  const std::string end = "end_header\n";
  const size_t body = ply.find(end);
  REQUIRE(body != std::string::npos);
  const std::string header = ply.substr(0, body + end.size());
  CHECK(header.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  CHECK(header.find("element vertex 2\n") != std::string::npos);
  for (const char* p : {"x", "y", "z", "vx", "vy", "vz"})
    CHECK(header.find(std::string("property float ") + p + "\n") != std::string::npos);
  REQUIRE(ply.size() == header.size() + 2 * 6 * sizeof(float));
  float second[6];
  std::memcpy(second, ply.data() + header.size() + 6 * sizeof(float), sizeof second);
  CHECK(second[0] == 1.5f);
  CHECK(second[1] == -2.0f);
  CHECK(second[3] == -1.0f);
  CHECK(second[5] == 8.0f);

  particles.velocities.pop_back();
  CHECK_THROWS_AS(liquid::encode_ply(particles), std::invalid_argument);
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
