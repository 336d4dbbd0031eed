#include "liquid/export/whitewater_ply.h"

#include "engine/io/atomic_file.h"
#include "liquid/export/frame_comments.h"

#include <bit>
#include <cstdint>
#include <cstring>

namespace liquid {

std::string encode_whitewater_ply(const std::vector<WhitewaterParticle>& particles, const WhitewaterPlyFrame& frame) {
  static_assert(std::endian::native == std::endian::little, "binary_little_endian PLY is written as-is");
  std::string out = "ply\nformat binary_little_endian 1.0\n"
                    "comment rasterization-liquids whitewater: x y z m, vx vy vz m/s, type, age s, "
                    "id = id_hi * 2^32 + id_lo\n"
                    "comment type 1 spray\ncomment type 2 foam\ncomment type 3 bubble\n" +
                    frame_comments("comment", frame.frame, frame.time_s, frame.fps) +
                    "element vertex " + std::to_string(particles.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float vx\nproperty float vy\nproperty float vz\n"
                    "property uchar type\nproperty float age\nproperty uint id_hi\nproperty uint id_lo\nend_header\n";
  // Packed, as PLY's binary vertices are: 6 floats, the type's byte, the age and the id's halves.
  constexpr size_t k_vertex_bytes = 6 * 4 + 1 + 4 + 2 * 4;
  const size_t header = out.size();
  out.resize(header + particles.size() * k_vertex_bytes);
  char* cursor = out.data() + header;
  for (const WhitewaterParticle& p : particles) {
    const float motion[6] = {p.position.x, p.position.y, p.position.z, p.velocity.x, p.velocity.y, p.velocity.z};
    const uint32_t id[2] = {uint32_t(p.id >> 32), uint32_t(p.id)};
    std::memcpy(cursor, motion, sizeof motion);
    cursor[24] = char(p.kind);
    std::memcpy(cursor + 25, &p.age, 4);
    std::memcpy(cursor + 29, id, sizeof id);
    cursor += k_vertex_bytes;
  }
  return out;
}

void write_whitewater_ply(const std::filesystem::path& path, const std::vector<WhitewaterParticle>& particles,
                          const WhitewaterPlyFrame& frame) {
  engine::io::write_file_atomically(path, encode_whitewater_ply(particles, frame));
}

}  // namespace liquid
