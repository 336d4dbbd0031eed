// The body integration pass: each dynamic obstacle's rigid-body step (semi-implicit Euler with an
// added-mass term, wall contact) from the body force pass's force and torque, one fragment per
// texel of the body-state texture. Shader: shaders/liquid/solver/body.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/body_force.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

class BodyIntegrationPass {
 public:
  BodyIntegrationPass(engine::vk::Context& context, const SolverVariant& variant,
                      const std::vector<int32_t>& specialization);

  // From the state `step.bodies` and the step's `force` into `step.body_targets`, then swaps the
  // two: `step.bodies` is the new state.
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
              const BodyForceImages& force) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
};

}  // namespace liquid
