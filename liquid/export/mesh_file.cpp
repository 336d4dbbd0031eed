#include "liquid/export/mesh_file.h"

#include "engine/io/atomic_file.h"
#include "liquid/error.h"
#include "liquid/export/frame_comments.h"

#include <bit>
#include <cstdio>
#include <algorithm>
#include <cstring>

namespace liquid {

namespace {

std::string encode_ply(const SurfaceMesh& mesh, const MeshFrame& frame) {
  static_assert(std::endian::native == std::endian::little, "binary_little_endian PLY is written as-is");
  std::string out = "ply\nformat binary_little_endian 1.0\n"
                    "comment rasterization-liquids surface: x y z m, vx vy vz m/s, triangles wound outward\n" +
                    frame_comments("comment", frame.frame, frame.time_s, frame.fps) +
                    "element vertex " + std::to_string(mesh.positions.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float vx\nproperty float vy\nproperty float vz\n"
                    "element face " + std::to_string(mesh.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  const size_t header = out.size();
  constexpr size_t k_vertex_bytes = 6 * 4, k_face_bytes = 1 + 3 * 4;
  out.resize(header + mesh.positions.size() * k_vertex_bytes + mesh.triangles.size() * k_face_bytes);
  char* cursor = out.data() + header;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    std::memcpy(cursor, &mesh.positions[i], 12);
    std::memcpy(cursor + 12, &mesh.velocities[i], 12);
    cursor += k_vertex_bytes;
  }
  for (const glm::uvec3& t : mesh.triangles) {
    *cursor = 3;
    const int32_t corners[3] = {int32_t(t.x), int32_t(t.y), int32_t(t.z)};
    std::memcpy(cursor + 1, corners, sizeof corners);
    cursor += k_face_bytes;
  }
  return out;
}

std::string encode_obj(const SurfaceMesh& mesh, const MeshFrame& frame) {
  std::string out = "# rasterization-liquids surface: positions in m, triangles wound outward\n" +
                    frame_comments("#", frame.frame, frame.time_s, frame.fps);
  char line[96];
  for (const glm::vec3& p : mesh.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const glm::uvec3& t : mesh.triangles) {  // OBJ counts vertices from 1
    std::snprintf(line, sizeof line, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
    out += line;
  }
  return out;
}

}  // namespace

std::string encode_mesh(const SurfaceMesh& mesh, const MeshFrame& frame, MeshFormat format) {
  if (mesh.velocities.size() != mesh.positions.size())
    throw ArgumentError("encode_mesh: " + std::to_string(mesh.positions.size()) + " positions but " +
                        std::to_string(mesh.velocities.size()) + " velocities");
  for (const glm::uvec3& t : mesh.triangles)
    if (std::max({t.x, t.y, t.z}) >= mesh.positions.size())
      throw ArgumentError("encode_mesh: a triangle indexes vertex " + std::to_string(std::max({t.x, t.y, t.z})) +
                          " of " + std::to_string(mesh.positions.size()));
  return format == MeshFormat::Ply ? encode_ply(mesh, frame) : encode_obj(mesh, frame);
}

void write_mesh(const std::filesystem::path& path, const SurfaceMesh& mesh, const MeshFrame& frame, MeshFormat format) {
  engine::io::write_file_atomically(path, encode_mesh(mesh, frame, format));
}

}  // namespace liquid
