// Triangle-mesh files (OBJ, binary and ASCII PLY) read with assimp, for the scene's mesh obstacles.
#pragma once

#include "liquid/scene.h"

#include <filesystem>

namespace liquid {

// The triangles of every mesh in the file, vertices welded by position, centred at the centre of
// their bounding box (the obstacle's `center` places that point). Throws SceneError "<path>: <what
// is wrong>" when the file cannot be read or the mesh is not closed (liquid/physics/mesh.h).
TriangleMesh load_mesh_file(const std::filesystem::path& path);

}  // namespace liquid
