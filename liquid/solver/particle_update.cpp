#include "liquid/solver/particle_update.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/images.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

namespace {

std::vector<engine::vk::DescriptorBinding> particle_bindings(bool meshes) {
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_PARTICLE_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_VELOCITIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_GRID_VELOCITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_body_shapes_binding(bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  add_mesh_field_binding(meshes, bindings);
  return bindings;
}

}  // namespace

ParticleUpdatePass::ParticleUpdatePass(engine::vk::Context& context, const GridLayout& layout,
                                       const std::vector<int32_t>& specialization, bool meshes)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.particle",
                    .vertex = engine::passes::fullscreen_vertex_shader(),
                    .fragment = mesh_variant(meshes,
                                             layout.pick(liquid_shaders::particle_frag_2d, liquid_shaders::particle_frag_3d,
                                                         liquid_shaders::particle_frag_3d_atlas),
                                             layout.pick(liquid_shaders::particle_frag_2d_mesh,
                                                         liquid_shaders::particle_frag_3d_mesh,
                                                         liquid_shaders::particle_frag_3d_atlas_mesh)),
                    .color_formats = {k_particle_format, k_particle_format},
                    .bindings = particle_bindings(meshes),
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR) {}

ParticleImages ParticleUpdatePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                          const ParticleImages& current, ImageHandle splat, const GridImages& grids,
                                          ImageHandle bodies, ImageHandle body_shapes, const ParticleImages& next, int active_after,
                                          ImageHandle mesh_field) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ParticleImages out;
  };
  return graph
      .add_pass<Data>(
          "liquid.particle",
          [&](PassBuilder& b, Data& d) {
            const VkSampler s = nearest_.handle();
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_POSITIONS, current.positions, s);
            d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_VELOCITIES, current.velocities, s);
            d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_SPLAT, splat, s);
            d.bindings.bind_image(b, LIQUID_BINDING_PARTICLE_GRID_VELOCITY, grids.velocity, s);
            d.bindings.bind_image(b, LIQUID_BINDING_BODIES, bodies, s);
            bind_body_shapes(d.bindings, b, body_shapes, linear_);
            bind_mesh_field(d.bindings, b, mesh_field, linear_);
            d.out.positions = b.write(next.positions, Access::ColorAttachmentWrite);
            d.out.velocities = b.write(next.velocities, Access::ColorAttachmentWrite);
          },
          [active_after](PassContext& ctx, const Data& d) {
            if (active_after == 0) return;
            d.bindings.bind_and_push(ctx);
            // Only the rows that hold active (or newly emitted) particles are shaded.
            const uint32_t rows = (uint32_t(active_after) + ctx.width - 1) / ctx.width;
            const VkRect2D scissor{{0, 0}, {ctx.width, rows}};
            vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
            engine::passes::draw_fullscreen(ctx.cmd);
          })
      .out;
}

}  // namespace liquid
