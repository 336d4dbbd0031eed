#include "liquid/solver/splat.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/images.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

#include <cmath>

namespace liquid {

namespace {

// In 3D each particle is drawn once per slice it may touch: the slice centres within r of it are
// at most ceil(2 r) consecutive layers (splat.vert). Every instance costs vertex shading, binning
// and point setup even when it is dropped, so no spare one is drawn.
uint32_t instances_per_particle(const SimulationSetup& setup) {
  return setup.dimension == 3 ? uint32_t(std::ceil(2.0f * setup.kernel_radius_cells)) : 1u;
}

// The vertex shader by the grid's layout (how a point reaches its slice).
std::span<const uint32_t> splat_vertex_shader(const GridLayout& layout) {
  if (layout.dimension == 2) return liquid_shaders::splat_vert_2d;
  if (layout.atlas()) return liquid_shaders::splat_vert_3d_atlas;
  return layout.path == GridPath::GeometryShader ? liquid_shaders::splat_vert_3d_gs : liquid_shaders::splat_vert_3d;
}

}  // namespace

engine::vk::GraphicsPipelineDesc particle_points_pipeline(const char* name, const GridLayout& layout,
                                                          std::span<const uint32_t> vertex,
                                                          std::span<const uint32_t> fragment, VkFormat format,
                                                          const std::vector<int32_t>& specialization) {
  return engine::vk::GraphicsPipelineDesc{
      .name = name,
      .vertex = vertex,
      .geometry = layout.layered() && layout.path == GridPath::GeometryShader
                      ? std::span<const uint32_t>(liquid_shaders::splat_geom)
                      : std::span<const uint32_t>{},
      .fragment = fragment,
      .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
      .color_formats = {format},
      .blend = {engine::vk::BlendMode::Additive},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {LIQUID_BINDING_SPLAT_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                   {LIQUID_BINDING_SPLAT_VELOCITIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .specialization = specialization};
}

SplatPass::SplatPass(engine::vk::Context& context, const SimulationSetup& setup, const GridLayout& layout,
                     VkFormat splat_format, const std::vector<int32_t>& specialization)
    : pipeline_(context, particle_points_pipeline(
                             "liquid.splat", layout, splat_vertex_shader(layout),
                             layout.atlas() ? liquid_shaders::splat_frag_atlas : liquid_shaders::splat_frag,
                             splat_format, specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      instances_(instances_per_particle(setup)) {}

ImageHandle SplatPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                              const ParticleImages& particles, ImageHandle splat, int active_particles) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle splat;
  };
  return graph
      .add_pass<Data>(
          "liquid.splat",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_POSITIONS, particles.positions, nearest_.handle());
            d.bindings.bind_image(b, LIQUID_BINDING_SPLAT_VELOCITIES, particles.velocities, nearest_.handle());
            d.splat = b.write(splat, Access::ColorAttachmentBlend, engine::graph::clear_to(0, 0, 0, 0));
          },
          [this, active_particles](PassContext& ctx, const Data& d) {
            if (active_particles == 0) return;
            d.bindings.bind_and_push(ctx);
            vkCmdDraw(ctx.cmd, uint32_t(active_particles), instances_, 0, 0);
          })
      .splat;
}

}  // namespace liquid
