// PLY triangle meshes (ascii, binary_little_endian, binary_big_endian) read strictly, for the mesh
// obstacles (mesh_file.h). Internal to liquid/scene/.
#pragma once

#include "liquid/scene.h"

#include <string>
#include <string_view>

namespace liquid {

// The vertices (element vertex: x, y, z of any numeric type) and faces (element face: a list
// vertex_indices or vertex_index, fan-triangulated) of a PLY file's bytes; every other element and
// property is skipped by its type. The header's counts are checked against the bytes that follow
// it before anything is allocated. Throws SceneError "<name>: <fault>", naming the header line, data
// line (ascii) or byte offset (binary) where the file goes wrong. Not welded, checked or centred.
TriangleMesh read_ply(std::string_view bytes, const std::string& name);

}  // namespace liquid
