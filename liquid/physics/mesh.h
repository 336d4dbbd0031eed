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
// the distance to the nearest triangle, both over a bounding-volume hierarchy of the triangles, so
// a query visits the boxes along its ray or near its point rather than every triangle (a mesh of
// millions of triangles is carved around in seconds).
class PlacedMesh {
 public:
  PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, float reach);
  PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, glm::quat rotation, float reach);
  float distance(glm::vec3 p) const;
  bool inside(glm::vec3 p) const;

 private:
  // A box of the hierarchy: its children are nodes_[first] and nodes_[first + 1], or, for a leaf
  // (count > 0), the triangles order_[first .. first + count).
  struct Node {
    glm::vec3 lo, hi;
    uint32_t first = 0, count = 0;
  };
  void build_hierarchy();
  float nearest_surface(glm::vec3 p, float within) const;
  int winding_above(glm::vec3 p) const;

  std::vector<glm::vec3> corners_;  // 3 per triangle, world
  glm::vec3 lo_{0.0f}, hi_{0.0f};
  float reach_ = 0.0f;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;  // triangles in leaf order
  // How far inside() moves its ray off the point: a sliver of the triangles' own extent.
  glm::vec3 ray_offset_{0.0f};
};

}  // namespace liquid
