// The host's own triangle mesh, laid out as its renderer keeps it: interleaved vertices (position
// and normal, split per face so each face shades flat) and 32-bit indices. The same bytes are drawn
// by the scene pass (pulled by gl_VertexIndex from a uniform buffer) and handed to the liquid as a
// mesh obstacle (liquid::mesh_obstacle with this vertex stride), so the water meets exactly what the
// host draws.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

// What the host's shader paints a surface with (the normal's w).
enum class HostMaterial { CheckeredFloor = 0, Paint = 1 };

struct HostVertex {
  glm::vec4 position;  // xyz m in the mesh's frame, w = 1
  glm::vec4 normal;    // xyz unit, w = the HostMaterial
};
static_assert(sizeof(HostVertex) == 32, "the layout scene.vert reads");

struct HostMesh {
  std::vector<HostVertex> vertices;
  std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
};

// A painted board (a box of the given half extents, centred on the origin): 24 vertices, 12 triangles.
HostMesh board_mesh(glm::vec3 half_extent);
// The floor: the square [-1, 1]^2 at y = 0, facing up.
HostMesh floor_mesh();
