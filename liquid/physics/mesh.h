// Triangle meshes placed in the world, on the CPU: their transform, and their signed distance for
// what the CPU does with obstacles (carving the initial lattice, counting particles inside in the
// diagnostics). The GPU's field is built by the rasterizer (liquid/solver/mesh_field.h); the check
// every mesh passes is liquid/scene/mesh_check.h.
#pragma once

#include "liquid/scene.h"
#include "liquid/scene/mesh_check.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace liquid {

// The mesh's local-to-world transform at obstacle centre `center`: center + rotation * (scale * v).
glm::mat4 mesh_to_world(const TriangleMesh& mesh, glm::vec3 center);
// The same turned by `rotation` instead of the mesh's own (an obstacle's pose's orientation).
glm::mat4 mesh_to_world(const TriangleMesh& mesh, glm::vec3 center, glm::quat rotation);

// Longest triangle edge, in the mesh's own frame (before scale).
float longest_edge(const TriangleMesh& mesh);

// A mesh at one pose: signed distance (m, negative inside) within `reach` of the surface, clamped to
// +-reach beyond it, like the GPU's field. Inside by the winding along +z (the rasterizer's test),
// distances from the triangles in buckets of about `reach`.
class PlacedMesh {
 public:
  PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, float reach);
  PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, glm::quat rotation, float reach);
  float distance(glm::vec3 p) const;
  bool inside(glm::vec3 p) const;

 private:
  std::vector<glm::vec3> corners_;  // 3 per triangle, world
  glm::vec3 lo_{0.0f}, hi_{0.0f};
  float reach_ = 0.0f;
  glm::ivec3 buckets_{1};
  glm::vec3 bucket_size_{1.0f};
  std::vector<std::vector<int>> bucket_triangles_;   // by (x, y, z)
  std::vector<std::vector<int>> column_triangles_;   // by (x, y): the triangles over a column
  glm::ivec3 bucket_of(glm::vec3 p) const;
};

}  // namespace liquid
