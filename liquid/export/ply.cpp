#include "liquid/export/ply.h"

#include "engine/io/atomic_file.h"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace liquid {

std::string encode_ply(const ParticleSnapshot& particles) {
  static_assert(std::endian::native == std::endian::little, "binary_little_endian PLY is written as-is");
  const size_t count = particles.positions.size();
  if (particles.velocities.size() != count)
    throw std::invalid_argument("encode_ply: " + std::to_string(count) + " positions but " +
                                std::to_string(particles.velocities.size()) + " velocities");
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment rasterization-liquids particles (m, m/s)\n"
                    "element vertex " + std::to_string(count) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float vx\nproperty float vy\nproperty float vz\nend_header\n";
  const size_t header = out.size();
  out.resize(header + count * 6 * sizeof(float));
  char* cursor = out.data() + header;
  for (size_t i = 0; i < count; ++i) {
    const float vertex[6] = {particles.positions[i].x,  particles.positions[i].y,  particles.positions[i].z,
                             particles.velocities[i].x, particles.velocities[i].y, particles.velocities[i].z};
    std::memcpy(cursor, vertex, sizeof(vertex));
    cursor += sizeof(vertex);
  }
  return out;
}

void write_ply(const std::filesystem::path& path, const ParticleSnapshot& particles) {
  engine::io::write_file_atomically(path, encode_ply(particles));
}

}  // namespace liquid
