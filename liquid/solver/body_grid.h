// The body grid pass: the grid pass's update without one dynamic obstacle (a full-screen pass over
// the grid on every 3D path, like the grid pass), for the body reaction pass to compare with.
// Shader: shaders/liquid/solver/body_grid.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

class BodyGridPass {
 public:
  BodyGridPass(engine::vk::Context& context, const GridLayout& layout, const std::vector<int32_t>& specialization);

  // u' (with the fluid flag) of the step's `splat` without obstacle `body`, into a new transient grid.
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle splat,
                     ImageHandle bodies, int body) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
  engine::vk::ImageDesc desc_;
};

}  // namespace liquid
