// Whitewater export (Scene::whitewater: spray, foam and bubbles; docs/whitewater.md) as binary
// little-endian PLY, one file a frame, read by Blender, Houdini and MeshLab as a point cloud with
// attributes. Each vertex is float x y z vx vy vz (m, m/s), uchar type (WhitewaterKind: 1 spray,
// 2 foam, 3 bubble), float age (s), uint id_hi and uint id_lo; the header names the types in
// comments (comment type 1 spray, ...) and gives the frame number and its simulated time.
#pragma once

#include "liquid/types.h"

#include <filesystem>
#include <string>
#include <vector>

namespace liquid {

// What one whitewater file holds besides the particles.
struct WhitewaterPlyFrame {
  int frame = 0;
  double time_s = 0.0;  // simulated time of the state
  double fps = 0.0;     // frames per simulated second of the sequence (a header comment; 0: none)
};

// The whole file: an ASCII header then one packed 37-byte vertex per particle, in the order given.
// The 64-bit WhitewaterParticle::id is written as two uint32, id_hi (its upper half: the slot) and
// id_lo (its lower half: the bits of the birth time, below 2^31 as the time is positive). PLY has
// no 64-bit integer type (its types stop at int and uint, then float and double), so no reader
// takes one, and a double holds an integer exactly only below 2^53. No particle: a valid file of
// 0 vertices.
std::string encode_whitewater_ply(const std::vector<WhitewaterParticle>& particles, const WhitewaterPlyFrame& frame);

// Writes encode_whitewater_ply() to a temporary file renamed into place, so an interrupted export
// never leaves a partial .ply. Throws std::runtime_error naming the path when it cannot be written.
void write_whitewater_ply(const std::filesystem::path& path, const std::vector<WhitewaterParticle>& particles,
                          const WhitewaterPlyFrame& frame);

}  // namespace liquid
