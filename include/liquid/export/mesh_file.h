// A frame's liquid surface as a triangle mesh file: binary little-endian PLY with a velocity per
// vertex (vx vy vz, m/s, for motion blur), or Wavefront OBJ (positions and faces only). The
// triangles wind counter-clockwise seen from outside the liquid (outward normals).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace liquid {

struct SurfaceMesh {
  std::vector<glm::vec3> positions;   // m
  std::vector<glm::vec3> velocities;  // m/s, one per position
  std::vector<glm::uvec3> triangles;  // indices into positions
};

enum class MeshFormat { Ply, Obj };

struct MeshFrame {
  int frame = 0;
  double time_s = 0.0;  // simulated time, a comment in the file's header
  double fps = 0.0;     // frames per simulated second (a comment; 0: none)
};

// The whole file. Throws ArgumentError when the velocities do not match the positions or a
// triangle indexes past them.
std::string encode_mesh(const SurfaceMesh& mesh, const MeshFrame& frame, MeshFormat format);

// Writes encode_mesh() through a temporary name renamed into place.
void write_mesh(const std::filesystem::path& path, const SurfaceMesh& mesh, const MeshFrame& frame, MeshFormat format);

}  // namespace liquid
