// Obstacles on the CPU: where each one is at a given time (scripted motion or set by the host) and
// its signed distance, the same functions the shaders evaluate (common.glsl). Used to fill the
// uniform block and by the diagnostics to count particles inside obstacles.
#pragma once

#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

// Scripted motion of the scene: center + velocity t + amplitude sin(2 pi f t), at the scene's
// rotation, not turning. (A dynamic obstacle's is where it starts.)
ObstaclePose scripted_pose(const Obstacle& obstacle, double time);

// Signed distance (m, negative inside) of `p` to the obstacle placed at `pose` (a box in its
// rotated frame); `dimension` 2 ignores z (a box is then the rectangle of its x and y extents).
// Metaballs use the same first-order estimate as the shader.
float obstacle_distance(const Obstacle& obstacle, const ObstaclePose& pose, glm::vec3 p, int dimension);

// The velocity of the obstacle's material at p: velocity + angular_velocity x (p - center).
glm::vec3 obstacle_velocity_at(const ObstaclePose& pose, glm::vec3 p);

}  // namespace liquid
