// Obstacles on the CPU: where each one is at a given time (scripted motion or set by the host) and
// its signed distance, the same functions the shaders evaluate (common.glsl). Used to fill the
// uniform block and by the diagnostics to count particles inside obstacles.
#pragma once

#include "liquid/physics/mesh.h"
#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <vector>

namespace liquid {

// Scripted motion of the scene: center + velocity t + amplitude sin(2 pi f t), turned by its spin
// (Obstacle::angular_velocity) from the scene's rotation. (A dynamic obstacle's is where it starts.)
ObstaclePose scripted_pose(const Obstacle& obstacle, double time);

// The scripted orientation at `time`: angleAxis(|w| t, w / |w|) * rotation, w the obstacle's spin.
glm::quat spun_rotation(const Obstacle& obstacle, double time);

// The constant angular velocity (rad/s, world frame) that turns `from` into `to` in `seconds`, the
// shorter way round; zero for no time or no turn.
glm::vec3 turn_rate(glm::quat from, glm::quat to, double seconds);

// Signed distance (m, negative inside) of `p` to the obstacle placed at `pose` (a box in its
// rotated frame); `dimension` 2 ignores z (a box is then the rectangle of its x and y extents).
// Metaballs use the same first-order estimate as the shader.
float obstacle_distance(const Obstacle& obstacle, const ObstaclePose& pose, glm::vec3 p, int dimension);

// The velocity of the obstacle's material at p: velocity + angular_velocity x (p - center).
glm::vec3 obstacle_velocity_at(const ObstaclePose& pose, glm::vec3 p);

// An obstacle at one position, for many distance queries: obstacle_distance() for the analytic
// shapes, a PlacedMesh for a mesh (its distance exact within `mesh_reach` of the surface, clamped
// to +-mesh_reach beyond; the sign everywhere). `dimension` 2 evaluates at z = 0, as the GPU does.
class PlacedObstacle {
 public:
  PlacedObstacle(const Obstacle& obstacle, const ObstaclePose& pose, int dimension, float mesh_reach);
  float distance(glm::vec3 p) const;

 private:
  const Obstacle* obstacle_;
  ObstaclePose pose_;
  int dimension_;
  std::optional<PlacedMesh> mesh_;
};

}  // namespace liquid
