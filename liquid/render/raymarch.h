// The 3D view (section 7, figure 3): an occupancy pass (per-brick maximum density, for empty-space
// skipping) and a full-screen raymarch of the density volume that writes colour and depth.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/node.h"
#include "liquid/render/camera.h"
#include "liquid/render/renderer.h"
#include "liquid/render/view_uniforms.h"

namespace liquid {

class RaymarchPass {
 public:
  RaymarchPass(engine::vk::Context& context, const LiquidNode& node);

  struct Outputs {
    engine::graph::ImageHandle color;
    engine::graph::ImageHandle depth;
  };
  Outputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const RenderSettings& settings,
                 const CameraView& camera);

  static constexpr int k_brick_cells = 4;  // occupancy block edge, in grid cells

 private:
  const LiquidNode& node_;
  engine::vk::GraphicsPipeline occupancy_;
  engine::vk::GraphicsPipeline raymarch_;
  engine::vk::Sampler linear_;
  engine::vk::Sampler nearest_;
  ViewUniforms uniforms_;
};

}  // namespace liquid
