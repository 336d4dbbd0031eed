// The solver's view of shaders/liquid/shared.h: the uniform block as C++ reads it. The layout is
// written once (in shared.h, which also gives the limits their C++ names); the static_asserts pin
// the nested structs' std140 offsets, and tests/cpu/test_shaders.cpp compares every member's with
// glslang's.
#pragma once

#include "shaders/liquid/shared.h"

#include <cstddef>

namespace liquid::gpu {

static_assert(k_wall_table_size % 4 == 0, "the wall table is packed into vec4s");
static_assert(sizeof(Obstacle) == 96 && offsetof(Obstacle, velocity) == 32 && offsetof(Obstacle, ball_count) == 48 &&
              offsetof(Obstacle, orientation) == 64 && offsetof(Obstacle, angular_velocity) == 80);
static_assert(sizeof(Body) == 48 && offsetof(Body, added_mass) == 28 && offsetof(Body, added_inertia_ratio) == 44);
static_assert(sizeof(Brush) == 32 && offsetof(Brush, acceleration) == 16);
static_assert(sizeof(EmitterRange) == 48 && offsetof(EmitterRange, end) == 32);
// SolverUniforms' offsets move with its scalars (LIQUID_SOLVER_SCALARS); the reflection test
// checks each against glslang's, and the arrays start on a 16-byte boundary as std140 requires.
static_assert(offsetof(SolverUniforms, wall_kernel_beyond) % 16 == 0 && sizeof(SolverUniforms) % 16 == 0);

}  // namespace liquid::gpu
