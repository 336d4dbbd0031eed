// The C++ side of shaders/liquid/shared.h: the solver's uniform block and the limits, under C++
// names. The layout is written once (in shared.h); the static_asserts pin the std140 offsets, and
// tests/cpu/test_shaders.cpp compares them with the offsets glslang gives the compiled shaders.
#pragma once

#include "shaders/liquid/shared.h"

#include <cstddef>

namespace liquid::gpu {

constexpr int k_max_obstacles = LIQUID_MAX_OBSTACLES;
constexpr int k_max_balls = LIQUID_MAX_BALLS;
constexpr int k_max_ground_hills = LIQUID_MAX_GROUND_HILLS;
constexpr int k_max_brushes = LIQUID_MAX_BRUSHES;
constexpr int k_max_emitters = LIQUID_MAX_EMITTERS;
constexpr int k_max_kernel_radius_cells = LIQUID_MAX_KERNEL_RADIUS_CELLS;
constexpr int k_wall_table_size = LIQUID_WALL_TABLE_SIZE;

constexpr int k_obstacle_sphere = LIQUID_OBSTACLE_SPHERE;
constexpr int k_obstacle_box = LIQUID_OBSTACLE_BOX;
constexpr int k_obstacle_metaballs = LIQUID_OBSTACLE_METABALLS;

static_assert(k_wall_table_size % 4 == 0, "the wall table is packed into vec4s");
static_assert(sizeof(Obstacle) == 64 && offsetof(Obstacle, velocity) == 32 && offsetof(Obstacle, ball_count) == 48);
static_assert(sizeof(Brush) == 32 && offsetof(Brush, acceleration) == 16);
static_assert(sizeof(EmitterRange) == 48 && offsetof(EmitterRange, end) == 32);
static_assert(offsetof(SolverUniforms, rest_depth) == 96);
static_assert(offsetof(SolverUniforms, wall_kernel_beyond) == 112);
static_assert(offsetof(SolverUniforms, obstacles) == 144);
static_assert(offsetof(SolverUniforms, balls) == 144 + 64 * k_max_obstacles);
static_assert(sizeof(SolverUniforms) == 144 + 64 * 8 + 16 * 32 + 16 * 16 + 32 * 4 + 48 * 4);

}  // namespace liquid::gpu
