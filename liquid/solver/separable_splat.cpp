#include "liquid/solver/separable_splat.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/splat.h"
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

// In 3D two targets of the same format: the lower slice's share and the upper one's.
engine::vk::GraphicsPipelineDesc deposit_pipeline(const GridLayout& layout, VkFormat format,
                                                  const std::vector<int32_t>& specialization) {
  const bool pair = layout.dimension == 3;
  engine::vk::GraphicsPipelineDesc d = particle_points_pipeline(
      "liquid.deposit", layout, deposit_vertex_shader(layout),
      pair ? liquid_shaders::deposit_frag_3d : liquid_shaders::deposit_frag_2d, format, specialization);
  if (pair) {
    d.color_formats.push_back(format);
    d.blend.push_back(engine::vk::BlendMode::Additive);
  }
  return d;
}

engine::vk::GraphicsPipelineDesc spread_z_pipeline(const GridLayout& layout, VkFormat format,
                                                   const std::vector<int32_t>& specialization, bool active_region) {
  const GridPassShaders shaders = grid_pass_shaders(layout, active_region);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_BLUR_SOURCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BLUR_SOURCE_UPPER, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_active_region_binding(active_region, bindings);
  return engine::vk::GraphicsPipelineDesc{
      .name = "liquid.splat_spread_z",
      .vertex = shaders.vertex,
      .geometry = shaders.geometry,
      .fragment = layout.atlas() ? liquid_shaders::splat_blur_frag_3d_atlas_z : liquid_shaders::splat_blur_frag_3d_z,
      .color_formats = {format},
      .bindings = bindings,
      .specialization = specialization};
}

}  // namespace

SeparableSplatPass::SeparableSplatPass(engine::vk::Context& context, const GridLayout& layout,
                                       VkFormat splat_format, const std::vector<int32_t>& specialization,
                                       bool active_region)
    : deposit_(context, deposit_pipeline(layout, splat_format, specialization)),
      spread_xy_(context, layout, SeparableBlur::Kind::Splat, splat_format, specialization, active_region),
      nearest_(context, VK_FILTER_NEAREST),
      scratch_desc_(layout.image_desc(splat_format, 0)),
      layout_(layout),
      active_region_(active_region) {
  if (layout.dimension == 3)
    spread_z_.emplace(context, spread_z_pipeline(layout, splat_format, specialization, active_region));
}

SeparableSplatPass::Deposit SeparableSplatPass::deposit(engine::graph::RenderGraph& graph,
                                                        const engine::vk::UniformSlice& uniforms,
                                                        const ParticleImages& particles, ImageHandle splat,
                                                        int active_particles) const {
  struct Data {
    engine::passes::PassBindings bindings;
    Deposit out;
  };
  const bool pair = spread_z_.has_value();
  const ImageHandle lower = pair ? graph.create_image("liquid.splat_scratch", scratch_desc_) : splat;
  const ImageHandle upper = pair ? graph.create_image("liquid.splat_upper", scratch_desc_) : ImageHandle{};
  return graph
      .add_pass<Data>(
          "liquid.deposit",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(deposit_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_POSITIONS, particles.positions, nearest_.handle());
            d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_VELOCITIES, particles.velocities, nearest_.handle());
            d.out.lower = b.write(lower, Access::ColorAttachmentBlend, engine::graph::clear_to(0, 0, 0, 0));
            if (pair) d.out.upper = b.write(upper, Access::ColorAttachmentBlend, engine::graph::clear_to(0, 0, 0, 0));
          },
          [active_particles](PassContext& ctx, const Data& d) {
            if (active_particles == 0) return;
            d.bindings.bind_and_push(ctx);
            vkCmdDraw(ctx.cmd, uint32_t(active_particles), 1, 0, 0);
          })
      .out;
}

ImageHandle SeparableSplatPass::spread(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                       const Deposit& deposit, ImageHandle splat, ImageHandle region) const {
  struct Spread {
    engine::passes::PassBindings bindings;
    ImageHandle out;
  };
  // 2D: the deposit is in `splat`, and the x and y passes take it to a scratch image and back.
  // 3D: the z pass writes `splat` from the deposit's two grids, then x and y as in 2D with the
  // deposit's lower grid as their scratch image.
  if (!spread_z_) {
    ImageHandle source = deposit.lower;
    ImageHandle scratch = graph.create_image("liquid.splat_scratch", scratch_desc_);
    return spread_xy_.add_to(graph, uniforms, source, scratch, region);
  }
  ImageHandle source = graph
                           .add_pass<Spread>(
                               "liquid.splat_spread_z",
                               [&](PassBuilder& b, Spread& d) {
                                 d.bindings = engine::passes::PassBindings(*spread_z_);
                                 d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
                                 d.bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE, deposit.lower, nearest_.handle());
                                 d.bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE_UPPER, deposit.upper,
                                                       nearest_.handle());
                                 d.out = b.write(splat, Access::ColorAttachmentWrite,
                                                 bind_active_region(d.bindings, b, region, active_region_, nearest_));
                               },
                               [this](PassContext& ctx, const Spread& d) {
                                 d.bindings.bind_and_push(ctx);
                                 draw_grid_cells(ctx, layout_, active_region_);
                               })
                           .out;
  ImageHandle scratch = deposit.lower;
  return spread_xy_.add_to(graph, uniforms, source, scratch, region);
}

}  // namespace liquid
