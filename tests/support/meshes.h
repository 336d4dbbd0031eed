// Closed triangle meshes for the tests, built in code: an icosphere (a subdivided icosahedron with
// its vertices on the sphere) and a box, counter-clockwise seen from outside.
#pragma once

#include "liquid/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace test {

inline liquid::TriangleMesh icosphere(float radius, int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> v{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::vec3& p : v) p = glm::normalize(p);
  std::vector<uint32_t> f{0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6,
                          7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    const auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, added] = middle.try_emplace(key, uint32_t(v.size()));
      if (added) v.push_back(glm::normalize(v[a] + v[b]));
      return it->second;
    };
    std::vector<uint32_t> g;
    for (size_t i = 0; i < f.size(); i += 3) {
      const uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = std::move(g);
  }
  liquid::TriangleMesh mesh;
  for (const glm::vec3& p : v) mesh.vertices.push_back(p * radius);
  mesh.indices = std::move(f);
  return mesh;
}

// A box of half extents `half` centred on the origin: 8 corners, 12 triangles.
inline liquid::TriangleMesh box_mesh(glm::vec3 half) {
  liquid::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back(half * glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f));
  // Corner i has x from bit 0, y from bit 1, z from bit 2; each face's two triangles counter-clockwise
  // seen from outside.
  mesh.indices = {0, 4, 6, 0, 6, 2,   // -x
                  1, 3, 7, 1, 7, 5,   // +x
                  0, 1, 5, 0, 5, 4,   // -y
                  2, 6, 7, 2, 7, 3,   // +y
                  0, 2, 3, 0, 3, 1,   // -z
                  4, 5, 7, 4, 7, 6};  // +z
  return mesh;
}

// A mesh obstacle of `mesh` at `center` (what a host builds with liquid::mesh_obstacle()).
inline liquid::Obstacle mesh_obstacle_of(const liquid::TriangleMesh& mesh, glm::vec3 center) {
  liquid::Obstacle o;
  o.shape = liquid::ObstacleShape::Mesh;
  o.center = center;
  o.mesh = mesh;
  return o;
}

}  // namespace test
