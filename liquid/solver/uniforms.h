// Fills the solver's per-step uniform block (shaders/liquid/shared.h) from the setup and the
// step's inputs (time, counts, obstacle poses, brushes, emitter ranges). Pure CPU code.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/gpu_types.h"
#include "liquid/types.h"

#include <vulkan/vulkan.h>

#include <vector>

namespace liquid {

// Every stage that may read the solver's block (it sits in common.glsl, which the liquid's vertex
// and fragment shaders include). No geometry shader reads it, so a device without geometry shaders
// never sees that stage named.
constexpr VkShaderStageFlags k_solver_uniform_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

struct EmissionRange {
  int emitter = 0;  // index into the scene's emitters
  int begin = 0;    // first particle index emitted this step
  int end = 0;      // one past the last
};

// A host's push on a dynamic obstacle (LiquidNode::set_body_force), through its centre.
struct BodyPush {
  glm::vec3 force{0.0f};   // N
  glm::vec3 torque{0.0f};  // N m
};

struct StepInputs {
  float dt = 0.0f;          // s
  int active_before = 0;    // particles alive at the start of the step
  int active_after = 0;     // after this step's emission
  std::vector<ObstaclePose> obstacle_poses;  // one per scene obstacle, at the end of the step
  std::vector<BodyPush> body_pushes;         // per scene obstacle (dynamic ones read it), or empty
  std::vector<ForceBrush> brushes;
  std::vector<EmissionRange> emissions;
};

// Throws ArgumentError when the step has more brushes or emitting emitters than the uniform
// block holds (limits in shaders/liquid/shared.h); the scene's own lists were checked when it
// entered the library (liquid/scene/limits.h).
gpu::SolverUniforms make_uniforms(const Scene& scene, const SimulationSetup& setup, const StepInputs& step);

// Throws ArgumentError ("liquid: N what (at most limit)") when count exceeds limit.
void require_at_most(size_t count, int limit, const char* what);

// The code shaders compare an obstacle's kind with (LIQUID_OBSTACLE_* in shared.h, its shape's
// value), plus LIQUID_OBSTACLE_DYNAMIC for a dynamic one (the OBSTACLE_KIND_i specialization
// constants).
int obstacle_code(const Obstacle& obstacle);

}  // namespace liquid
