// Section 5, the particle update: one fragment per particle texel writes the new position and
// velocity (two render targets): velocity by the PIC/FLIP blend of the grid's u and u', position
// by RK2 through u'; texels in an emitter's range are spawned at its nozzle.
// Shader: shaders/liquid/solver/particle.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

class ParticleUpdatePass {
 public:
  // `meshes`: the scene has mesh obstacles, whose field add_to() then reads.
  ParticleUpdatePass(engine::vk::Context& context, const GridLayout& layout, const std::vector<int32_t>& specialization,
                     bool meshes = false);

  // From `current` into `next` (the other texture of the ping-pong pair), for the rows holding
  // `active_after` particles; `bodies`: the dynamic obstacles' state at the end of the step, with
  // `body_shapes` (liquid/solver/body_shapes.h).
  ParticleImages add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                        const ParticleImages& current, ImageHandle splat, const GridImages& grids, ImageHandle bodies,
                        ImageHandle body_shapes, const ParticleImages& next, int active_after, ImageHandle mesh_field = {}) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
  engine::vk::Sampler linear_;  // the mesh field and the body shapes
};

}  // namespace liquid
