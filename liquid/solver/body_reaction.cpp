#include "liquid/solver/body_reaction.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

namespace {
struct BodyReactionPush {
  int32_t body;
  float particle_mass;
};
}  // namespace

BodyReactionPass::BodyReactionPass(engine::vk::Context& context, const GridLayout& layout, int obstacles,
                                   float particle_mass, const std::vector<int32_t>& specialization)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.body_reaction",
                    .vertex = layout.pick(liquid_shaders::body_reaction_vert_2d, liquid_shaders::body_reaction_vert_3d,
                                          liquid_shaders::body_reaction_vert_3d_atlas),
                    .fragment = liquid_shaders::body_reaction_frag,
                    .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
                    .color_formats = {k_body_format, k_body_format},
                    .blend = {engine::vk::BlendMode::Additive, engine::vk::BlendMode::Additive},
                    .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                 {LIQUID_BINDING_PARTICLE_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                                 {LIQUID_BINDING_PARTICLE_GRID_VELOCITY, DescriptorKind::SampledImage,
                                  VK_SHADER_STAGE_VERTEX_BIT},
                                 {LIQUID_BINDING_BODY_GRID_VELOCITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                                 {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
                    .push_constant_size = sizeof(BodyReactionPush),
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      obstacles_(uint32_t(obstacles)),
      particle_mass_(particle_mass) {}

BodyReactionImages BodyReactionPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                            ImageHandle positions, ImageHandle grid_velocity,
                                            const std::vector<BodyWithout>& bodies_without, ImageHandle bodies,
                                            int active) const {
  const engine::vk::ImageDesc desc{engine::vk::ImageKind::Image2D, 1, obstacles_, 1, k_body_format, 0};
  BodyReactionImages out{graph.create_image("liquid.body_force", desc), graph.create_image("liquid.body_torque", desc)};
  // One pass per body (each binds its own u'_b), adding into the targets the first one clears.
  for (size_t i = 0; i < bodies_without.size(); ++i) {
    const BodyWithout& without = bodies_without[i];
    const engine::graph::AttachmentOptions start =
        i == 0 ? engine::graph::clear_to(0, 0, 0, 0) : engine::graph::AttachmentOptions{engine::graph::LoadOp::Load, {}};
    struct Data {
      engine::passes::PassBindings bindings;
      BodyReactionImages out;
    };
    out = graph
              .add_pass<Data>(
                  "liquid.body_reaction",
                  [&](PassBuilder& b, Data& d) {
                    const VkSampler s = nearest_.handle();
                    d.bindings = engine::passes::PassBindings(pipeline_);
                    d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
                    d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_POSITIONS, positions, s);
                    d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_GRID_VELOCITY, grid_velocity, s);
                    d.bindings.bind_image(b, LIQUID_BINDING_BODY_GRID_VELOCITY, without.grid_velocity, s);
                    d.bindings.bind_image(b, LIQUID_BINDING_BODIES, bodies, s);
                    d.out.force = b.write(out.force, Access::ColorAttachmentBlend, start);
                    d.out.torque = b.write(out.torque, Access::ColorAttachmentBlend, start);
                  },
                  [this, body = without.body, active](PassContext& ctx, const Data& d) {
                    d.bindings.bind_and_push(ctx);
                    pipeline_.push_constants(ctx.cmd, BodyReactionPush{body, particle_mass_});
                    if (active > 0) vkCmdDraw(ctx.cmd, uint32_t(active), 1, 0, 0);  // a point per particle
                  })
              .out;
  }
  return out;
}

}  // namespace liquid
