#include "liquid/solver/separable_splat.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

namespace {

// The vertex shader by the grid's layout (how a point reaches its slice), as the chapter's splat.
std::span<const uint32_t> deposit_vertex_shader(const GridLayout& layout) {
  if (layout.dimension == 2) return liquid_shaders::deposit_vert_2d;
  if (layout.atlas()) return liquid_shaders::deposit_vert_3d_atlas;
  return layout.path == GridPath::GeometryShader ? liquid_shaders::deposit_vert_3d_gs : liquid_shaders::deposit_vert_3d;
}

}  // namespace

SeparableSplatPass::SeparableSplatPass(engine::vk::Context& context, const GridLayout& layout,
                                       VkFormat splat_format, const std::vector<int32_t>& specialization)
    : deposit_(context,
               engine::vk::GraphicsPipelineDesc{
                   .name = "liquid.deposit",
                   .vertex = deposit_vertex_shader(layout),
                   .geometry = layout.layered() && layout.path == GridPath::GeometryShader
                                   ? std::span<const uint32_t>(liquid_shaders::splat_geom)
                                   : std::span<const uint32_t>{},
                   .fragment = liquid_shaders::deposit_frag,
                   .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
                   .color_formats = {splat_format},
                   .blend = {engine::vk::BlendMode::Additive},
                   .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                {LIQUID_BINDING_SPLAT_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                                {LIQUID_BINDING_SPLAT_VELOCITIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
                   .specialization = specialization}),
      spread_(context, layout, SeparableBlur::Kind::Splat, splat_format, specialization),
      nearest_(context, VK_FILTER_NEAREST),
      scratch_desc_(layout.image_desc(splat_format, 0)),
      instances_(layout.dimension == 3 ? 2u : 1u) {}

ImageHandle SeparableSplatPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                       const ParticleImages& particles, ImageHandle splat, int active_particles) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle deposit;
  };
  // The spread alternates between two images and must end in `splat`: with an odd number of axes
  // the deposit goes to the scratch image, with an even number to `splat` itself.
  ImageHandle scratch = graph.create_image("liquid.splat_scratch", scratch_desc_);
  const bool odd_axes = spread_.passes() % 2 == 1;
  ImageHandle deposit =
      graph
          .add_pass<Data>(
              "liquid.deposit",
              [&](PassBuilder& b, Data& d) {
                d.bindings = engine::passes::PassBindings(deposit_);
                d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
                d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_POSITIONS, particles.positions, nearest_.handle());
                d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_VELOCITIES, particles.velocities, nearest_.handle());
                d.deposit = b.write(odd_axes ? scratch : splat, Access::ColorAttachmentBlend,
                                    engine::graph::clear_to(0, 0, 0, 0));
              },
              [this, active_particles](PassContext& ctx, const Data& d) {
                if (active_particles == 0) return;
                d.bindings.bind_and_push(ctx);
                vkCmdDraw(ctx.cmd, uint32_t(active_particles), instances_, 0, 0);
              })
          .deposit;
  if (odd_axes) return spread_.add_to(graph, uniforms, deposit, splat);
  return spread_.add_to(graph, uniforms, deposit, scratch);
}

}  // namespace liquid
