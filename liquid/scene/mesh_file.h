// Triangle-mesh files (OBJ, binary and ASCII PLY) for the scene's mesh obstacles, read by the
// project's own strict readers (obj_reader.h, ply_reader.h; limits in mesh_parse.h).
#pragma once

#include "liquid/scene.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace liquid {

// The triangles of the file, vertices welded by position, centred at the centre of their bounding
// box (the obstacle's `center` places that point). Throws SceneError "<path>: <what is wrong>" when
// the path is not a regular file of at most k_max_mesh_file_bytes (following symlinks: "is a
// directory", "is a device", "is a FIFO"), the file is malformed, or the mesh is not closed
// (liquid/physics/mesh.h).
TriangleMesh load_mesh_file(const std::filesystem::path& path);

// The same from the file's bytes: a PLY file when they begin with the line "ply", else an OBJ file
// when `name` ends in .obj; `name` prefixes every message. The fuzzer's entry point.
TriangleMesh parse_mesh(std::string_view bytes, const std::string& name);

}  // namespace liquid
