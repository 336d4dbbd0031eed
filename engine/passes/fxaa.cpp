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

// The edge marks between the two passes (fxaa.frag with and without MARK): 0 or 1 a quad.
constexpr VkFormat k_edge_format = VK_FORMAT_D16_UNORM;

vk::GraphicsPipelineDesc fxaa_pipeline_desc(VkFormat format, bool mark) {
  return vk::GraphicsPipelineDesc{
      .name = mark ? "fxaa.mark" : "fxaa",
      .vertex = fullscreen_vertex_shader(),
      .fragment = mark ? engine_shaders::fxaa_mark_frag : engine_shaders::fxaa_frag,
      .color_formats = {format},
      .depth_format = k_edge_format,
      .depth_test = true,
      .depth_write = mark,
      // The mark pass writes every pixel's mark; the full pass, drawn at depth 0, runs where it is 1.
      .depth_compare = mark ? VK_COMPARE_OP_ALWAYS : VK_COMPARE_OP_LESS,
      .bindings = {{0, vk::DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
      .push_constant_size = sizeof(FxaaPush)};
}

}  // namespace

FxaaPass::FxaaPass(vk::Context& context, VkFormat format)
    : mark_(context, fxaa_pipeline_desc(format, true)),
      pipeline_(context, fxaa_pipeline_desc(format, false)),
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
    graph::ImageHandle edges;
  };
  const FxaaPush push{{1.0f / float(in.width), 1.0f / float(in.height)},
                      settings.edge_threshold,
                      settings.edge_threshold_min,
                      settings.subpixel_quality};
  // Pass one: every pixel copied, the quads with an edge marked in depth.
  const Data& marked = graph.add_pass<Data>(
      name + ".mark",
      [&](graph::PassBuilder& builder, Data& d) {
        d.bindings = PassBindings(mark_);
        d.bindings.bind_image(builder, 0, input, sampler_.handle());
        d.output = builder.write(output, graph::Access::ColorAttachmentWrite);
        const vk::ImageDesc edges{vk::ImageKind::Image2D, in.width, in.height, 1, k_edge_format, 0};
        d.edges = builder.write(builder.create(name + ".edges", edges), graph::Access::DepthAttachmentWrite);
      },
      [this, push](graph::PassContext& ctx, const Data& d) {
        d.bindings.bind_and_push(ctx);
        mark_.push_constants(ctx.cmd, push);
        draw_fullscreen(ctx.cmd);
      });
  const graph::ImageHandle copied = marked.output, edges = marked.edges;
  // Pass two: FXAA where the marks let it through, over the copy.
  const Data& data = graph.add_pass<Data>(
      name,
      [&](graph::PassBuilder& builder, Data& d) {
        d.bindings = PassBindings(pipeline_);
        d.bindings.bind_image(builder, 0, input, sampler_.handle());
        d.output = builder.write(copied, graph::Access::ColorAttachmentWrite, {graph::LoadOp::Load, {}});
        d.edges = builder.write(edges, graph::Access::DepthAttachmentWrite, {graph::LoadOp::Load, {}});
      },
      [this, push](graph::PassContext& ctx, const Data& d) {
        d.bindings.bind_and_push(ctx);
        pipeline_.push_constants(ctx.cmd, push);
        draw_fullscreen(ctx.cmd);
      });
  return data.output;
}

}  // namespace engine::passes
