// Section 5, the particle update: one fragment per particle texel writes the new position and
// velocity (two render targets, and C_p's under the affine transfer): velocity by the PIC/FLIP
// blend of the grid's u and u', position by RK2 through u' (and, with the scene's
// position_correction, out of over-packed cells by the separable splat's deposit); texels in an
// emitter's range are spawned at its nozzle.
// Shader: shaders/liquid/solver/particle.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

class ParticleUpdatePass {
 public:
  ParticleUpdatePass(engine::vk::Context& context, const SolverVariant& variant,
                     const std::vector<int32_t>& specialization);

  // From `step.particles` into `step.particle_targets` (the other textures of the ping-pong pair),
  // for the rows holding `active_after` particles, then swaps the two: `step.particles` are the new
  // ones. Reads the step's splat and grids, the body state at the end of the step with the body
  // shapes, the mesh field (with meshes) and the separable splat's deposit (with the position
  // correction).
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
              int active_after) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
  engine::vk::Sampler linear_;  // the mesh field and the body shapes
  SolverVariant variant_;
};

}  // namespace liquid
