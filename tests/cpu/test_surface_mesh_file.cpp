// The surface's mesh files: binary PLY with a velocity per vertex and triangles as index lists, and
// OBJ with positions and faces counted from 1.
#include "liquid/error.h"
#include "liquid/export/mesh_file.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <string>

namespace {

// A tetrahedron wound outward, each vertex moving along +x at its index in m/s.
liquid::SurfaceMesh tetrahedron() {
  liquid::SurfaceMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (size_t i = 0; i < mesh.positions.size(); ++i) mesh.velocities.emplace_back(float(i), 0.0f, 0.0f);
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

}  // namespace

TEST_CASE("the surface mesh as PLY holds positions velocities and triangles after its header", "[export]") {
  const std::string ply = liquid::encode_mesh(tetrahedron(), {12, 0.25, 30.0}, liquid::MeshFormat::Ply);
  const std::string end = "end_header\n";
  const size_t body = ply.find(end) + end.size();
  const std::string header = ply.substr(0, body);
  CHECK(header.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  CHECK(header.find("comment frame 12\ncomment time_s 0.25\ncomment fps 30\n") != std::string::npos);
  CHECK(header.find("element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float vx\nproperty float vy\nproperty float vz\n"
                    "element face 4\nproperty list uchar int vertex_indices\n") != std::string::npos);
  REQUIRE(ply.size() == body + 4 * 24 + 4 * 13);
  float vertex[6];
  std::memcpy(vertex, ply.data() + body + 3 * 24, sizeof vertex);  // the fourth vertex
  CHECK(vertex[2] == 1.0f);
  CHECK(vertex[3] == 3.0f);
  const char* face = ply.data() + body + 4 * 24 + 3 * 13;  // the fourth triangle
  int32_t corners[3];
  std::memcpy(corners, face + 1, sizeof corners);
  CHECK(face[0] == 3);
  CHECK((corners[0] == 1 && corners[1] == 2 && corners[2] == 3));
}

TEST_CASE("the surface mesh as OBJ counts vertices from one", "[export]") {
  const std::string obj = liquid::encode_mesh(tetrahedron(), {3, 0.1, 0.0}, liquid::MeshFormat::Obj);
  CHECK(obj.find("# frame 3\n# time_s 0.10000000000000001\n") != std::string::npos);
  CHECK(obj.find("fps") == std::string::npos);
  CHECK(obj.find("v 0 0 1\n") != std::string::npos);
  CHECK(obj.find("f 2 3 4\n") != std::string::npos);
  CHECK(obj.find("f 1 3 2\n") != std::string::npos);
}

TEST_CASE("the surface mesh refuses velocities that do not match and triangles past the vertices", "[export]") {
  liquid::SurfaceMesh mesh = tetrahedron();
  mesh.velocities.pop_back();
  CHECK_THROWS_AS(liquid::encode_mesh(mesh, {}, liquid::MeshFormat::Ply), liquid::ArgumentError);
  mesh = tetrahedron();
  mesh.triangles.push_back({0, 1, 4});
  CHECK_THROWS_WITH(liquid::encode_mesh(mesh, {}, liquid::MeshFormat::Obj), Catch::Contains("vertex 4 of 4"));
}
