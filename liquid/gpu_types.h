// C++ mirror of the solver's uniform block (shaders/liquid/common.glsl, std140). Every member is a
// 16-byte vector so the layouts match without padding rules; static_asserts keep them in step.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>

namespace liquid::gpu {

constexpr int k_max_obstacles = 8;
constexpr int k_max_balls = 32;
constexpr int k_max_ground = 16;
constexpr int k_max_brushes = 4;
constexpr int k_max_emitters = 4;

constexpr float k_obstacle_sphere = 0.0f;
constexpr float k_obstacle_box = 1.0f;
constexpr float k_obstacle_metaballs = 2.0f;

struct Obstacle {
  glm::vec4 center_kind;
  glm::vec4 size;
  glm::vec4 velocity;
};

struct Brush {
  glm::vec4 position_radius;
  glm::vec4 acceleration;
};

struct EmitterRange {
  glm::vec4 position_radius;
  glm::vec4 velocity;
  glm::ivec4 range;
};

struct SolverUniforms {
  glm::vec4 domain_h;
  glm::ivec4 grid_dim;
  glm::vec4 gravity_dt;
  glm::vec4 pressure;
  glm::vec4 kernel;
  glm::ivec4 counts;
  glm::ivec4 counts2;
  glm::vec4 shallow;
  glm::vec4 wall_kernel_beyond[2];  // kernel mass beyond a wall k + 0.5 cells away, k = 0..7
  Obstacle obstacles[k_max_obstacles];
  glm::vec4 balls[k_max_balls];
  glm::vec4 ground[k_max_ground];
  Brush brushes[k_max_brushes];
  EmitterRange emitters[k_max_emitters];
};

static_assert(sizeof(Obstacle) == 48);
static_assert(sizeof(EmitterRange) == 48);
static_assert(offsetof(SolverUniforms, obstacles) == 160);
static_assert(offsetof(SolverUniforms, balls) == 160 + 48 * k_max_obstacles);
static_assert(sizeof(SolverUniforms) == 160 + 48 * 8 + 16 * 32 + 16 * 16 + 32 * 4 + 48 * 4);

}  // namespace liquid::gpu
