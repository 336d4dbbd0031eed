#include "host_mesh.h"

HostMesh board_mesh(glm::vec3 half_extent) {
  HostMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {1.0f, -1.0f}) {
      // The face's outward normal n and two tangents u, v with u x v = n, so the corners below run
      // counter-clockwise seen from outside.
      glm::vec3 n(0.0f), u(0.0f), v(0.0f);
      n[axis] = side;
      u[(axis + 1) % 3] = 1.0f;
      v = glm::cross(n, u);
      const uint32_t first = uint32_t(mesh.vertices.size());
      for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        mesh.vertices.push_back({glm::vec4((n + corner.x * u + corner.y * v) * half_extent, 1.0f), glm::vec4(n, float(HostMaterial::Paint))});
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
    }
  }
  return mesh;
}

HostMesh floor_mesh() {
  HostMesh mesh;
  const glm::vec4 up(0.0f, 1.0f, 0.0f, float(HostMaterial::CheckeredFloor));
  for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1)})
    mesh.vertices.push_back({glm::vec4(corner.x, 0.0f, corner.y, 1.0f), up});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}
