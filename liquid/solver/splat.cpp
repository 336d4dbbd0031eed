#include "liquid/solver/splat.h"

#include "liquid/solver/separable_splat.h"
#include "liquid/solver/solver_pass.h"
#include "liquid_shader_families.h"

#include <cmath>

namespace liquid {

namespace {

// In 3D each particle is drawn once per slice it may touch: the slice centres within r of it are
// at most ceil(2 r) consecutive layers (splat.vert). Every instance costs vertex shading, binning
// and point setup even when it is dropped, so no spare one is drawn.
uint32_t instances_per_particle(const SimulationSetup& setup) {
  return setup.dimension == 3 ? uint32_t(std::ceil(2.0f * setup.kernel_radius_cells)) : 1u;
}

}  // namespace

engine::vk::GraphicsPipelineDesc particle_points_pipeline(const char* name, const SolverVariant& variant,
                                                          std::span<const uint32_t> vertex,
                                                          std::span<const uint32_t> fragment, VkFormat format,
                                                          const std::vector<int32_t>& specialization) {
  const GridLayout& layout = variant.layout;
  engine::vk::GraphicsPipelineDesc desc{
      .name = name,
      .vertex = vertex,
      .geometry = layout.layered() && layout.path == GridPath::GeometryShader
                      ? shader_variant(shaders::splat_geom, variant.shader_features())
                      : std::span<const uint32_t>{},
      .fragment = fragment,
      .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
      .color_formats = {format},
      .blend = {engine::vk::BlendMode::Additive},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {LIQUID_BINDING_SPLAT_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                   {LIQUID_BINDING_SPLAT_VELOCITIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .specialization = specialization};
  for (int a = 0; a < variant.affine_textures(); ++a)
    desc.bindings.push_back({uint32_t(LIQUID_BINDING_SPLAT_AFFINE + a), DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT});
  return desc;
}

void bind_particle_points(engine::passes::PassBindings& bindings, PassBuilder& builder, const ParticleImages& particles,
                          const engine::vk::Sampler& nearest) {
  bindings.bind_image(builder, LIQUID_BINDING_SPLAT_POSITIONS, particles.positions, nearest.handle());
  bindings.bind_image(builder, LIQUID_BINDING_SPLAT_VELOCITIES, particles.velocities, nearest.handle());
  for (size_t a = 0; a < particles.affine.size(); ++a)
    if (particles.affine[a].valid())
      bindings.bind_image(builder, uint32_t(LIQUID_BINDING_SPLAT_AFFINE + int(a)), particles.affine[a], nearest.handle());
}

SplatPass::SplatPass(engine::vk::Context& context, const SolverVariant& variant, const SimulationSetup& setup,
                     VkFormat splat_format, const std::vector<int32_t>& specialization)
    : pipeline_(context, particle_points_pipeline("liquid.splat", variant, variant.shader(shaders::splat_vert),
                                                  variant.shader(shaders::splat_frag), splat_format, specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      instances_(instances_per_particle(setup)) {
  if (variant.active_region) active_region_.emplace(context, variant.layout, specialization);
}

void SplatPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
                       int active) const {
  step.splat = add_solver_pass<ImageHandle>(
      graph, pipeline_, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        bind_particle_points(bindings, b, step.particles, nearest_);
        return b.write(step.splat, Access::ColorAttachmentBlend, engine::graph::clear_to(0, 0, 0, 0));
      },
      [this, active](const PassContext& ctx) {
        if (active > 0) vkCmdDraw(ctx.cmd, uint32_t(active), instances_, 0, 0);
      });
  step.region = active_region_ ? active_region_->add_to(graph, uniforms, step.splat) : ImageHandle{};
}

std::unique_ptr<SplatStage> make_splat_stage(engine::vk::Context& context, const SolverVariant& variant,
                                             const SimulationSetup& setup, VkFormat splat_format,
                                             const std::vector<int32_t>& specialization) {
  if (variant.splat == SplatMode::Separable)
    return std::make_unique<SeparableSplatPass>(context, variant, splat_format, specialization);
  return std::make_unique<SplatPass>(context, variant, setup, splat_format, specialization);
}

}  // namespace liquid
