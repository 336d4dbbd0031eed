// The scene features that every shader including shaders/liquid/common.glsl is specialized for:
// obstacle count and shapes, shallow water, an integer gamma, emitters, the ground's hills, a wall
// table of zeros (constant_id i = entry i).
// They are fixed for a node's lifetime; obstacle poses, brushes and particle counts are not.
// Why specialize at all: see the comment above the constants in common.glsl.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/solver/gpu_types.h"

#include <cstdint>
#include <vector>

namespace liquid {

// The constant_id of each feature in common.glsl (tests/cpu/test_shaders.cpp reads the ids back
// from the compiled SPIR-V and compares).
namespace specialization_id {
constexpr size_t obstacle_count = 0;         // OBSTACLE_COUNT
constexpr size_t first_obstacle_kind = 1;    // OBSTACLE_KIND_0 .. OBSTACLE_KIND_7
constexpr size_t shallow_water = first_obstacle_kind + size_t(gpu::k_max_obstacles);  // SHALLOW_WATER
constexpr size_t integer_gamma = shallow_water + 1;                           // INTEGER_GAMMA
constexpr size_t has_emitters = integer_gamma + 1;                            // HAS_EMITTERS
constexpr size_t ground_hills = has_emitters + 1;                             // GROUND_HILLS
constexpr size_t walls_continued = ground_hills + 1;                          // WALLS_CONTINUED
constexpr size_t count = walls_continued + 1;
}  // namespace specialization_id

std::vector<int32_t> scene_specialization(const Scene& scene, const SimulationSetup& setup);

}  // namespace liquid
