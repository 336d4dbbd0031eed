#include "liquid/solver/body_integration.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

BodyIntegrationPass::BodyIntegrationPass(engine::vk::Context& context, int dimension,
                                         const std::vector<int32_t>& specialization)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.body",
                    .vertex = engine::passes::fullscreen_vertex_shader(),
                    .fragment = dimension == 2 ? liquid_shaders::body_frag_2d : liquid_shaders::body_frag_3d,
                    .color_formats = {k_body_format},
                    .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                 {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_BODY_FORCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_BODY_TORQUE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST) {}

ImageHandle BodyIntegrationPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                        ImageHandle current, const BodyForceImages& force, ImageHandle next) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle out;
  };
  return graph
      .add_pass<Data>(
          "liquid.body",
          [&](PassBuilder& b, Data& d) {
            const VkSampler s = nearest_.handle();
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_BODIES, current, s);
            d.bindings.bind_image(b, LIQUID_BINDING_BODY_FORCE, force.force, s);
            d.bindings.bind_image(b, LIQUID_BINDING_BODY_TORQUE, force.torque, s);
            d.out = b.write(next, Access::ColorAttachmentWrite);
          },
          [](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            engine::passes::draw_fullscreen(ctx.cmd);
          })
      .out;
}

}  // namespace liquid
