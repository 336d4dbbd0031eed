// Particle export as binary PLY, a format Blender, Houdini and MeshLab read as a point cloud with
// attributes. Each vertex is float x y z vx vy vz (m, m/s), int id, float density (rho/rho0); the
// header's comments give the frame number and its simulated time.
#pragma once

#include "liquid/types.h"

#include <filesystem>
#include <string>
#include <vector>

namespace liquid {

// What one PLY file holds besides the particles.
struct PlyFrame {
  int frame = 0;
  double time_s = 0.0;         // simulated time of the state
  std::vector<float> density;  // rho/rho0 per particle, same order as the particles
  double fps = 0.0;            // frames per simulated second of the sequence (a header comment; 0: none)
};

// The whole file: an ASCII header then one packed little-endian vertex per particle. The id is the
// particle's index, which the solver keeps for its whole life (texel i of the particle texture is
// particle i; emitters fill the next free texels), so it identifies a particle across frames.
// Throws ArgumentError when the arrays' lengths differ.
std::string encode_ply(const ParticleSnapshot& particles, const PlyFrame& frame);

// Writes encode_ply() to a temporary file renamed into place, so an interrupted export never leaves
// a partial .ply. Throws std::runtime_error naming the path when it cannot be written.
void write_ply(const std::filesystem::path& path, const ParticleSnapshot& particles, const PlyFrame& frame);

}  // namespace liquid
