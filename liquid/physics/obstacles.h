// Obstacles on the CPU: where each one is at a given time (scripted motion or set by the host) and
// its signed distance, the same functions the shaders evaluate. Used to fill the uniform block and
// by the diagnostics to count particles inside obstacles.
#pragma once

#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

// Scripted motion of the scene: center + velocity t + amplitude sin(2 pi f t).
ObstaclePose scripted_pose(const Obstacle& obstacle, double time);

// Signed distance (m, negative inside) of `p` to the obstacle placed at `center`; `dimension` 2
// ignores z. Metaballs use the same first-order estimate as the shader.
float obstacle_distance(const Obstacle& obstacle, glm::vec3 center, glm::vec3 p, int dimension);

}  // namespace liquid
