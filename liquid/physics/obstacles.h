// Obstacles on the CPU: where each one is at a given time (scripted motion or set by the host) and
// its signed distance, the same functions the shaders evaluate. Used to fill the uniform block and
// by the diagnostics to count particles inside obstacles.
#pragma once

#include "liquid/physics/mesh.h"
#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace liquid {

// Scripted motion of the scene: center + velocity t + amplitude sin(2 pi f t).
ObstaclePose scripted_pose(const Obstacle& obstacle, double time);

// Signed distance (m, negative inside) of `p` to the obstacle placed at `center`; `dimension` 2
// ignores z. Metaballs use the same first-order estimate as the shader.
float obstacle_distance(const Obstacle& obstacle, glm::vec3 center, glm::vec3 p, int dimension);

// An obstacle at one position, for many distance queries: obstacle_distance() for the analytic
// shapes, a PlacedMesh for a mesh (its distance exact within `mesh_reach` of the surface, clamped
// to +-mesh_reach beyond; the sign everywhere). `dimension` 2 evaluates at z = 0, as the GPU does.
class PlacedObstacle {
 public:
  PlacedObstacle(const Obstacle& obstacle, glm::vec3 center, int dimension, float mesh_reach);
  float distance(glm::vec3 p) const;

 private:
  const Obstacle* obstacle_;
  glm::vec3 center_;
  int dimension_;
  std::optional<PlacedMesh> mesh_;
};

}  // namespace liquid
