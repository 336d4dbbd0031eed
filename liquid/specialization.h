// The scene features that every shader including shaders/liquid/common.glsl is specialized for:
// obstacle count and shapes, shallow water, an integer gamma, emitters (constant_id i = entry i).
// They are fixed for a node's lifetime; obstacle poses, brushes and particle counts are not.
// Why specialize at all: see the comment on FEATURES_FIXED in common.glsl.
#pragma once

#include "liquid/setup.h"

#include <cstdint>
#include <vector>

namespace liquid {

std::vector<int32_t> scene_specialization(const SimulationSetup& setup);

}  // namespace liquid
