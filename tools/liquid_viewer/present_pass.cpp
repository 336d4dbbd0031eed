#include "tools/liquid_viewer/present_pass.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "viewer_shaders.h"

#include <stdexcept>

namespace viewer {

PresentPass::PresentPass(engine::vk::Context& context, VkFormat swapchain_format)
    : pipeline_(context, engine::vk::GraphicsPipelineDesc{
                             .name = "viewer.present",
                             .vertex = engine::passes::fullscreen_vertex_shader(),
                             .fragment = viewer_shaders::present_frag,
                             .color_formats = {swapchain_format},
                             .bindings = {{0, engine::vk::DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}}}),
      sampler_(context, VK_FILTER_NEAREST) {}

engine::graph::ImageHandle PresentPass::add_to(engine::graph::RenderGraph& graph, engine::graph::ImageHandle input,
                                               engine::graph::ImageHandle target) const {
  const engine::vk::ImageDesc& in = graph.image_desc(input);
  const engine::vk::ImageDesc& out = graph.image_desc(target);
  if (in.width != out.width || in.height != out.height)
    throw std::logic_error("viewer.present: the frame and the swapchain image differ in size");
  struct Data {
    engine::passes::PassBindings bindings;
    engine::graph::ImageHandle output;
  };
  const Data& data = graph.add_pass<Data>(
      "viewer.present",
      [&](engine::graph::PassBuilder& b, Data& d) {
        d.bindings = engine::passes::PassBindings(pipeline_);
        d.bindings.bind_image(b, 0, input, sampler_.handle());
        d.output = b.write(target, engine::graph::Access::ColorAttachmentWrite);
      },
      [](engine::graph::PassContext& ctx, const Data& d) {
        d.bindings.bind_and_push(ctx);
        engine::passes::draw_fullscreen(ctx.cmd);
      });
  return data.output;
}

}  // namespace viewer
