#include "liquid/export/ply.h"

#include "engine/io/atomic_file.h"
#include "liquid/export/frame_comments.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace liquid {

std::string encode_ply(const ParticleSnapshot& particles, const PlyFrame& frame) {
  static_assert(std::endian::native == std::endian::little, "binary_little_endian PLY is written as-is");
  const size_t count = particles.positions.size();
  if (particles.velocities.size() != count || frame.density.size() != count)
    throw ArgumentError("encode_ply: " + std::to_string(count) + " positions but " +
                        std::to_string(particles.velocities.size()) + " velocities and " +
                        std::to_string(frame.density.size()) + " densities");
  std::string out = "ply\nformat binary_little_endian 1.0\n"
                    "comment rasterization-liquids particles: x y z m, vx vy vz m/s, id, density rho/rho0\n" +
                    frame_comments("comment", frame.frame, frame.time_s, frame.fps) +
                    "element vertex " + std::to_string(count) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float vx\nproperty float vy\nproperty float vz\n"
                    "property int id\nproperty float density\nend_header\n";
  constexpr size_t k_vertex_bytes = 8 * 4;
  const size_t header = out.size();
  out.resize(header + count * k_vertex_bytes);
  char* cursor = out.data() + header;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec4& p = particles.positions[i];
    const glm::vec4& v = particles.velocities[i];
    const float motion[6] = {p.x, p.y, p.z, v.x, v.y, v.z};
    const int32_t id = int32_t(i);
    std::memcpy(cursor, motion, sizeof motion);
    std::memcpy(cursor + 24, &id, 4);
    std::memcpy(cursor + 28, &frame.density[i], 4);
    cursor += k_vertex_bytes;
  }
  return out;
}

void write_ply(const std::filesystem::path& path, const ParticleSnapshot& particles, const PlyFrame& frame) {
  engine::io::write_file_atomically(path, encode_ply(particles, frame));
}

}  // namespace liquid
