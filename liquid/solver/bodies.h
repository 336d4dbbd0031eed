// The body-state texture on the CPU side (its layout is shaders/liquid/shared.h's LIQUID_BODY_*):
// its first contents from the scene, and the dynamic obstacles' state decoded from a read-back.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

// Texels per row (one row per obstacle).
int gpu_body_texels();

// LIQUID_BODY_TEXELS x max(1, obstacles) texels, row by row: each dynamic obstacle at its scene
// pose, velocity, rotation and angular velocity, its last acceleration gravity (so the added-mass
// term does not slow a free fall); other rows zero.
std::vector<glm::vec4> initial_body_texels(const Scene& scene, const SimulationSetup& setup);

// The dynamic obstacles' state from the texture's texels, in scene order.
std::vector<BodyState> decode_bodies(const Scene& scene, int dimension, const std::vector<glm::vec4>& texels);

}  // namespace liquid
