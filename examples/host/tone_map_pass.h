// The host's tone map as a pass of its own on the liquid's render graph: after the liquid has been
// composited into the HDR scene, it maps the scene to the display image (ACES filmic curve, gamma).
// A host pass declares what it reads and writes like the library's passes, so the graph orders it
// after the composite and places the barriers.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"

class ToneMapPass {
 public:
  static constexpr VkFormat k_display_format = VK_FORMAT_R8G8B8A8_UNORM;

  explicit ToneMapPass(engine::vk::Context& context);

  // Reads `scene` (linear HDR), writes `display` (k_display_format, the same size), darkened inside
  // `backdrop` (a HUD panel's, drawn next; empty: none); returns `display`'s new version.
  engine::graph::ImageHandle add_to(engine::graph::RenderGraph& graph, engine::graph::ImageHandle scene,
                                    engine::graph::ImageHandle display, VkRect2D backdrop = {}) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler sampler_;
};
