#include "liquid/scene/obstacle_checks.h"

#include "liquid/scene/format.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
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

// Half the obstacle's extent along each world axis at its initial pose, about `center`.
glm::vec3 half_reach(const Obstacle& o) {
  const glm::mat3 turn = glm::mat3_cast(o.rotation);
  switch (o.shape) {
    case ObstacleShape::Sphere:
      return glm::vec3(o.radius);
    case ObstacleShape::Box: {
      glm::vec3 reach(0.0f);
      for (int column = 0; column < 3; ++column) reach += glm::abs(turn[column]) * o.half_extent[column];
      return reach;
    }
    case ObstacleShape::Mesh: {
      // The mesh's vertices are about the centre of its bounding box, which `center` places.
      glm::vec3 reach(0.0f);
      for (const glm::vec3& v : o.mesh.vertices) reach = glm::max(reach, glm::abs(turn * (o.mesh.scale * v)));
      return reach;
    }
    case ObstacleShape::Metaballs:
      break;
  }
  glm::vec3 reach(0.0f);
  for (const Metaball& ball : o.balls) reach = glm::max(reach, glm::abs(ball.center) + ball.radius);
  return reach;
}

const char* shape_name(ObstacleShape shape) {
  switch (shape) {
    case ObstacleShape::Sphere: return "sphere";
    case ObstacleShape::Box: return "box";
    case ObstacleShape::Mesh: return "mesh";
    case ObstacleShape::Metaballs: break;
  }
  return "metaballs";
}

}  // namespace

void check_obstacle_placement(const Scene& scene) {
  const std::string source = scene.source.empty() ? scene.name : scene.source;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    const std::string where = source + ": obstacles[" + std::to_string(i) + "]: ";
    if (o.shape == ObstacleShape::Mesh && !o.mesh.indices.empty() && six_signed_volume(o.mesh) < 0.0)
      throw SceneError(where + (o.mesh.file.empty() ? "the host's mesh" : o.mesh.file) +
                       ": is inside out (its triangles wind clockwise seen from outside, so its volume is "
                       "negative); reverse the order of each face's corners");
    if (!o.dynamic) continue;
    const glm::vec3 reach = half_reach(o);
    for (int a = 0; a < scene.dimension; ++a) {
      const char axis = "xyz"[a];
      const float lo = o.center[a] - reach[a], hi = o.center[a] + reach[a];
      // A hair of slack for a body resting exactly on a wall, written with rounded decimals.
      const float slack = 1e-5f * scene.domain[a];
      if (2.0f * reach[a] > scene.domain[a] + slack)
        throw SceneError(where + "the dynamic " + shape_name(o.shape) + " is " + format_number(2.0f * reach[a]) +
                         " m across along " + axis + ", wider than the domain's " + format_number(scene.domain[a]) +
                         " m; a body must fit inside the domain");
      if (lo < -slack || hi > scene.domain[a] + slack)
        throw SceneError(where + "the dynamic " + shape_name(o.shape) + " reaches " + axis + " = " +
                         format_number(lo < -slack ? lo : hi) + " m, outside the domain's [0, " +
                         format_number(scene.domain[a]) + "] m; a body must start wholly inside the domain");
    }
  }
}

}  // namespace liquid
