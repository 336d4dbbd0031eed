// Particle export as binary PLY (little-endian float x y z vx vy vz per vertex), a format Blender,
// Houdini and MeshLab read as a point cloud with velocity attributes.
#pragma once

#include "liquid/diagnostics.h"

#include <filesystem>
#include <string>

namespace liquid {

// The whole file: an ASCII header then `count` packed vertices of six little-endian floats.
std::string encode_ply(const ParticleSnapshot& particles);

// Writes encode_ply() to a temporary file renamed into place, so an interrupted export never leaves
// a partial .ply. Throws std::runtime_error naming the path when it cannot be written.
void write_ply(const std::filesystem::path& path, const ParticleSnapshot& particles);

}  // namespace liquid
