// The last pass of the viewer's graph: the renderer's RGBA8 frame drawn into the imported
// swapchain image (a full-screen triangle reading it texel for texel). Rendering, not a blit:
// the attachment's format converts the channel order (RGBA -> BGRA), and the graph's
// ColorAttachmentWrite / FragmentSampled accesses give the barriers.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"

namespace viewer {

class PresentPass {
 public:
  PresentPass(engine::vk::Context& context, VkFormat swapchain_format);
  // Returns the target's new version. `input` and `target` must have the same size.
  engine::graph::ImageHandle add_to(engine::graph::RenderGraph& graph, engine::graph::ImageHandle input,
                                    engine::graph::ImageHandle target) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler sampler_;
};

}  // namespace viewer
