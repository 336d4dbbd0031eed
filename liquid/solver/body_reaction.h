// The body reaction pass: the liquid's force and torque on each dynamic obstacle over one step,
// reduced on the raster pipeline by additive blending: one point per particle into the obstacle's
// texel of two 1 x N RGBA32F targets, one draw per dynamic obstacle.
// Shader: shaders/liquid/solver/body_reaction.vert.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

struct BodyReactionImages {
  ImageHandle force;   // texel (0, i): N on obstacle i
  ImageHandle torque;  // texel (0, i): N m about its centre
};

// One dynamic obstacle's input: its index and BodyGridPass's u' without it.
struct BodyWithout {
  int body = 0;
  ImageHandle grid_velocity;
};

class BodyReactionPass {
 public:
  BodyReactionPass(engine::vk::Context& context, const GridLayout& layout, int obstacles, float particle_mass,
                   const std::vector<int32_t>& specialization);

  // From the step's particles before their update (`positions`, the first `active` of them), the grid
  // pass's `grid_velocity`, each body's u' without it, and the body state the grid pass read.
  BodyReactionImages add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                            ImageHandle positions, ImageHandle grid_velocity, const std::vector<BodyWithout>& bodies_without,
                            ImageHandle bodies, int active) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
  uint32_t obstacles_ = 0;
  float particle_mass_ = 0.0f;
};

}  // namespace liquid
