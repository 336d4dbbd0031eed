// Mesh obstacles on the CPU: the scene key and its files (OBJ, ASCII and binary PLY), the refusal
// of meshes that cannot be obstacles in one line naming the file, a host's buffers, and the
// placed mesh's signed distance against the sphere it approximates.
#include "liquid/node.h"
#include "liquid/physics/mesh.h"
#include "liquid/physics/obstacles.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// A folder of its own for one test's files.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rasterliquids_mesh_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A 2D scene with one mesh obstacle whose "file" is `file` (relative to the scene).
std::string scene_with_mesh(const std::string& file, const std::string& extra = "") {
  return R"({ "dimension": 2, "domain": [1, 0.6], "grid_resolution": 32, "particle_spacing": 0.02,
    "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.3, 0.2] } ],
    "obstacles": [ { "shape": "mesh", "file": ")" + file + R"(", "center": [0.6, 0.3])" + extra + R"( } ] })";
}

liquid::Scene load(const fs::path& dir, const std::string& file, const std::string& extra = "") {
  write(dir / "scene.json", scene_with_mesh(file, extra));
  return liquid::load_scene(dir / "scene.json");
}

// A tetrahedron, counter-clockwise from outside.
const char* k_tetrahedron_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string refusal(const fs::path& dir, const std::string& file) {
  try {
    load(dir, file);
  } catch (const liquid::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a mesh obstacle is read from OBJ and PLY files relative to the scene, centred on its box",
          "[scene][mesh]") {
  const fs::path dir = scratch("read");
  write(dir / "tetra.obj", k_tetrahedron_obj);
  write(dir / "tetra_ascii.ply",
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  {
    std::ofstream ply(dir / "tetra_binary.ply", std::ios::binary);
    ply << "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    ply.write(reinterpret_cast<const char*>(v), sizeof(v));
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
      const unsigned char n = 3;
      ply.write(reinterpret_cast<const char*>(&n), 1);
      ply.write(reinterpret_cast<const char*>(f), sizeof(f));
    }
  }
  for (const char* file : {"tetra.obj", "tetra_ascii.ply", "tetra_binary.ply"}) {
    INFO(file);
    const liquid::Scene scene = load(dir, file, R"(, "rotation": [0, 0, 90], "scale": 0.1)");
    REQUIRE(scene.obstacles.size() == 1);
    const liquid::Obstacle& o = scene.obstacles[0];
    REQUIRE(o.shape == liquid::ObstacleShape::Mesh);
    CHECK(o.mesh.vertices.size() == 4);
    CHECK(o.mesh.indices.size() == 12);
    CHECK(o.mesh.scale == Approx(0.1f));
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& v : o.mesh.vertices) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    CHECK(glm::length(lo + hi) < 1e-6f);  // centred on its bounding box
    // Rotated 90 degrees about z: the local x axis points along world y.
    const glm::vec3 x = o.mesh.rotation * glm::vec3(1, 0, 0);
    CHECK(x.y == Approx(1.0f).margin(1e-6));
  }
}

TEST_CASE("meshes that cannot be obstacles are refused in one line naming the file and the fault", "[scene][mesh]") {
  const fs::path dir = scratch("refused");
  // Open: the tetrahedron without its last face.
  write(dir / "open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  // Inconsistent: one face turned inside out (its edges run the same way as its neighbours').
  write(dir / "flipped.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 4 3\n");
  write(dir / "empty.obj", "v 0 0 0\nv 1 0 0\n");
  // Degenerate: two triangles back to back, closed but flat.
  write(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n");
  write(dir / "garbage.ply",
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 0\nproperty list uchar int vertex_indices\nend_header\nnot numbers\n");
  const struct {
    const char* file;
    const char* fault;
  } cases[] = {{"open.obj", "not closed"},        {"flipped.obj", "not closed"},
               {"empty.obj", "has no triangle faces"},  {"flat.obj", "degenerate extent"},
               {"missing.obj", "no such mesh file"}, {"garbage.ply", "`not`"}};
  for (const auto& c : cases) {
    const std::string message = refusal(dir, c.file);
    INFO(c.file << ": " << message);
    CHECK_FALSE(message.empty());
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.find((dir / "scene.json").string() + ": obstacles[0].file: ") == 0);
    CHECK(message.find((dir / c.file).string()) != std::string::npos);
    CHECK(message.find(c.fault) != std::string::npos);
  }
}

TEST_CASE("a host's interleaved vertex buffer makes a mesh obstacle, an open one is refused", "[scene][mesh]") {
  // Position then a normal: 24 bytes a vertex. The tetrahedron's corners are split per face, as
  // flat-shaded buffers are, and welded back by position.
  const glm::vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const uint32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::vector<float> buffer;
  std::vector<uint32_t> indices;
  for (const auto& f : faces)
    for (uint32_t k : f) {
      indices.push_back(uint32_t(buffer.size() / 6));
      buffer.insert(buffer.end(), {corners[k].x, corners[k].y, corners[k].z, 0.0f, 0.0f, 1.0f});
    }
  const liquid::Obstacle o =
      liquid::mesh_obstacle(std::as_bytes(std::span(buffer)), 6 * sizeof(float), indices, glm::vec3(0.5f), "boat");
  CHECK(o.shape == liquid::ObstacleShape::Mesh);
  CHECK(o.mesh.vertices.size() == 4);
  CHECK(o.mesh.indices.size() == 12);
  indices.resize(9);  // three faces: open
  try {
    liquid::mesh_obstacle(std::as_bytes(std::span(buffer)), 6 * sizeof(float), indices, glm::vec3(0.5f), "boat");
    FAIL("an open mesh was accepted");
  } catch (const liquid::SceneError& e) {
    CHECK(std::string(e.what()).find("boat: the mesh is not closed") == 0);
  }
}

TEST_CASE("a placed mesh sphere's signed distance matches the sphere's", "[mesh]") {
  const float radius = 0.1f;
  const liquid::TriangleMesh mesh = test::icosphere(radius, 3);
  REQUIRE(liquid::mesh_problem(mesh).empty());
  const glm::vec3 center(0.3f, 0.2f, 0.25f);
  const float reach = 0.05f;
  const liquid::PlacedMesh placed(mesh, center, reach);
  float worst = 0.0f;
  int inside_mismatch = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 p = center + glm::vec3(float((i * 37) % 101) / 100.0f - 0.5f, float((i * 53) % 97) / 96.0f - 0.5f,
                                           float((i * 71) % 89) / 88.0f - 0.5f) * 0.3f;
    const float exact = glm::length(p - center) - radius;
    if ((exact < 0.0f) != placed.inside(p) && std::abs(exact) > 1e-3f) ++inside_mismatch;
    if (std::abs(exact) < reach * 0.9f) worst = std::max(worst, std::abs(placed.distance(p) - exact));
  }
  INFO("worst distance error " << worst << " m");
  CHECK(inside_mismatch == 0);
  CHECK(worst < 0.01f * radius + 1e-3f);
  // Whatever the reach (the views ask with an unbounded one), the inside is the sphere's: the ray's
  // sliver off the point is a sliver of the mesh, not of the reach.
  const liquid::PlacedMesh unbounded(mesh, center, 1e30f);
  CHECK(unbounded.inside(center));
  CHECK(unbounded.distance(center) == Approx(-radius).margin(0.02f * radius));
  CHECK_FALSE(unbounded.inside(center + glm::vec3(0.0f, 2.0f * radius, 0.0f)));
}

TEST_CASE("a mesh enclosing the whole domain with the liquid inside it is refused", "[scene][mesh]") {
  // A cube 20 m wide about a pool 1 m wide: the liquid would start inside the obstacle. Wound
  // inward (a room's walls seen from inside) it is refused as inside out when read; wound outward,
  // when the set-up finds every particle inside it.
  const fs::path dir = scratch("enclosing");
  liquid::TriangleMesh cube = test::box_mesh(glm::vec3(10.0f));
  std::string obj;
  for (const glm::vec3& v : cube.vertices)
    obj += "v " + std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
  std::string outward = obj, inward = obj;
  for (size_t t = 0; t < cube.indices.size(); t += 3) {
    const uint32_t a = cube.indices[t] + 1, b = cube.indices[t + 1] + 1, c = cube.indices[t + 2] + 1;
    outward += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    inward += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\n";
  }
  write(dir / "outward.obj", outward);
  write(dir / "inward.obj", inward);
  REQUIRE_THROWS_WITH(load(dir, "inward.obj"), Catch::Contains("inward.obj: is inside out"));
  const liquid::Scene scene = load(dir, "outward.obj");
  REQUIRE_THROWS_WITH(liquid::make_setup(scene, {}), Catch::Contains("obstacles: cover every particle of the fluid blocks"));
}
