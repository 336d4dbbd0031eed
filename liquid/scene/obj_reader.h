// Wavefront OBJ triangle meshes read strictly, for the mesh obstacles (mesh_file.h). Internal to
// liquid/scene/.
#pragma once

#include "liquid/scene.h"

#include <string>
#include <string_view>

namespace liquid {

// The vertices (`v x y z [w]`, or `v x y z r g b` with colours) and faces (`f a b c ...`, each
// corner `v`, `v/vt`, `v/vt/vn` or `v//vn`, negative indices counting back from the latest, polygons
// fan-triangulated) of an OBJ file's bytes. vt, vn, vp, o, g, s, usemtl, mtllib, l, p and comments
// are accepted and ignored; any other statement is refused. Throws SceneError "<name>: line N:
// <fault>". Not welded, checked or centred.
TriangleMesh read_obj(std::string_view bytes, const std::string& name);

}  // namespace liquid
