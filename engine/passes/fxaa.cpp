#include "engine/passes/fxaa.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "engine_shaders.h"

#include <stdexcept>

namespace engine::passes {
namespace {

struct FxaaPush {
  float inverse_size[2];
  float edge_threshold;
  float edge_threshold_min;
  float subpixel_quality;
};

}  // namespace

FxaaPass::FxaaPass(vk::Context& context, VkFormat format)
    : pipeline_(context, vk::GraphicsPipelineDesc{
                             .name = "fxaa",
                             .vertex = fullscreen_vertex_shader(),
                             .fragment = engine_shaders::fxaa_frag,
                             .color_formats = {format},
                             .bindings = {{0, vk::DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                             .push_constant_size = sizeof(FxaaPush)}),
      sampler_(context, VK_FILTER_LINEAR),
      format_(format) {}

graph::ImageHandle FxaaPass::add_to(graph::RenderGraph& graph, graph::ImageHandle input,
                                    const FxaaSettings& settings, const std::string& name) const {
  vk::ImageDesc desc = graph.image_desc(input);
  desc.usage = 0;
  return add_to(graph, input, graph.create_image(name + ".output", desc), settings, name);
}

graph::ImageHandle FxaaPass::add_to(graph::RenderGraph& graph, graph::ImageHandle input, graph::ImageHandle output,
                                    const FxaaSettings& settings, const std::string& name) const {
  const vk::ImageDesc& in = graph.image_desc(input);
  const vk::ImageDesc& out = graph.image_desc(output);
  if (in.format != format_ || in.kind != vk::ImageKind::Image2D)
    throw std::logic_error("fxaa: input '" + graph.image_name(input) + "' is not a 2D image of the pass's format");
  if (output.id == input.id || out.format != format_ || out.kind != vk::ImageKind::Image2D || out.width != in.width ||
      out.height != in.height)
    throw std::logic_error("fxaa: output '" + graph.image_name(output) + "' is not another 2D image of the input's size and format");
  struct Data {
    PassBindings bindings;
    graph::ImageHandle output;
  };
  const Data& data = graph.add_pass<Data>(
      name,
      [&](graph::PassBuilder& builder, Data& d) {
        d.bindings = PassBindings(pipeline_);
        d.bindings.bind_image(builder, 0, input, sampler_.handle());
        d.output = builder.write(output, graph::Access::ColorAttachmentWrite);
      },
      [this, settings](graph::PassContext& ctx, const Data& d) {
        d.bindings.bind_and_push(ctx);
        const FxaaPush push{{1.0f / float(ctx.width), 1.0f / float(ctx.height)},
                            settings.edge_threshold,
                            settings.edge_threshold_min,
                            settings.subpixel_quality};
        pipeline_.push_constants(ctx.cmd, push);
        draw_fullscreen(ctx.cmd);
      });
  return data.output;
}

}  // namespace engine::passes
