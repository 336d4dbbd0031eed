// The check every mesh obstacle passes when it enters the library (a file's in mesh_file.cpp, a
// host's in mesh_obstacle(), a scene built in code in check_list_limits()).
#pragma once

#include "liquid/scene.h"

#include <string>

namespace liquid {

// Merges vertices at identical positions (files and hosts split them by normal or texture
// coordinate), drops triangles that repeat a vertex, and re-indexes.
void weld_positions(TriangleMesh& mesh);

// What makes `mesh` unusable as an obstacle, or "" when it is closed: no triangles, an index out of
// range, a degenerate extent, edges not shared by exactly two triangles of opposite orientation, or
// triangles that wind inward (a negative volume).
std::string mesh_problem(const TriangleMesh& mesh);

}  // namespace liquid
