#include "tone_map_pass.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "host_shaders.h"

#include <glm/glm.hpp>

ToneMapPass::ToneMapPass(engine::vk::Context& context)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "host.tone_map",
                    .vertex = engine::passes::fullscreen_vertex_shader(),
                    .fragment = host_shaders::tone_map_frag,
                    .color_formats = {k_display_format},
                    .bindings = {{0, engine::vk::DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                    .push_constant_size = sizeof(glm::ivec4)}),
      sampler_(context, VK_FILTER_NEAREST) {}

engine::graph::ImageHandle ToneMapPass::add_to(engine::graph::RenderGraph& graph, engine::graph::ImageHandle scene,
                                               engine::graph::ImageHandle display, VkRect2D backdrop) const {
  struct Data {
    engine::passes::PassBindings bindings;
    engine::graph::ImageHandle display;
  };
  return graph
      .add_pass<Data>(
          "host.tone_map",
          [&](engine::graph::PassBuilder& builder, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_image(builder, 0, scene, sampler_.handle());
            d.display = builder.write(display, engine::graph::Access::ColorAttachmentWrite);
          },
          [this, rect = glm::ivec4(backdrop.offset.x, backdrop.offset.y,
                                   backdrop.offset.x + int32_t(backdrop.extent.width),
                                   backdrop.offset.y + int32_t(backdrop.extent.height))](engine::graph::PassContext& ctx,
                                                                                          const Data& d) {
            d.bindings.bind_and_push(ctx);
            pipeline_.push_constants(ctx.cmd, rect);
            engine::passes::draw_fullscreen(ctx.cmd);
          })
      .display;
}
