#include "liquid/solver/body_integration.h"

#include "engine/passes/fullscreen.h"
#include "liquid/solver/solver_pass.h"
#include "liquid/solver/state.h"
#include "liquid_shader_families.h"

#include <utility>

namespace liquid {

BodyIntegrationPass::BodyIntegrationPass(engine::vk::Context& context, const SolverVariant& variant,
                                         const std::vector<int32_t>& specialization)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.body",
                    .vertex = engine::passes::fullscreen_vertex_shader(),
                    .fragment = variant.shader(shaders::body_frag),
                    .color_formats = {k_body_format},
                    .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                 {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_BODY_FORCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_BODY_TORQUE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST) {}

void BodyIntegrationPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                 StepImages& step, const BodyForceImages& force) const {
  step.body_targets = add_solver_pass<ImageHandle>(
      graph, pipeline_, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        const VkSampler s = nearest_.handle();
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, s);
        bindings.bind_image(b, LIQUID_BINDING_BODY_FORCE, force.force, s);
        bindings.bind_image(b, LIQUID_BINDING_BODY_TORQUE, force.torque, s);
        return b.write(step.body_targets, Access::ColorAttachmentWrite);
      },
      [](const PassContext& ctx) { engine::passes::draw_fullscreen(ctx.cmd); });
  std::swap(step.bodies, step.body_targets);
}

}  // namespace liquid
