#include "liquid/scene/obstacle_checks.h"

#include <glm/glm.hpp>

#include <string>

namespace liquid {
namespace {

// Six times the signed volume the triangles enclose: positive when they wind counter-clockwise seen
// from outside.
double six_signed_volume(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[t]]), b(mesh.vertices[mesh.indices[t + 1]]),
        c(mesh.vertices[mesh.indices[t + 2]]);
    sum += glm::dot(a, glm::cross(b, c));
  }
  return sum;
}

}  // namespace

void check_mesh_winding(const Scene& scene) {
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    if (o.shape != ObstacleShape::Mesh || o.mesh.indices.empty() || six_signed_volume(o.mesh) >= 0.0) continue;
    throw SceneError((scene.source.empty() ? scene.name : scene.source) + ": obstacles[" + std::to_string(i) +
                     "]: " + (o.mesh.file.empty() ? "the host's mesh" : o.mesh.file) +
                     ": is inside out (its triangles wind clockwise seen from outside, so its volume is "
                     "negative); reverse the order of each face's corners");
  }
}

}  // namespace liquid
