#include "liquid/solver/separable_splat.h"

#include "liquid/solver/solver_pass.h"
#include "liquid/solver/splat.h"
#include "liquid_shader_families.h"

namespace liquid {

namespace {

// In 3D two targets of the same format: the lower slice's share and the upper one's.
engine::vk::GraphicsPipelineDesc deposit_pipeline(const SolverVariant& variant, VkFormat format,
                                                  const std::vector<int32_t>& specialization) {
  engine::vk::GraphicsPipelineDesc d =
      particle_points_pipeline("liquid.deposit", variant, variant.shader(shaders::deposit_vert),
                               variant.shader(shaders::deposit_frag), format, specialization);
  if (variant.layout.dimension == 3) {
    d.color_formats.push_back(format);
    d.blend.push_back(engine::vk::BlendMode::Additive);
  }
  return d;
}

engine::vk::GraphicsPipelineDesc spread_z_pipeline(const SolverVariant& variant, VkFormat format,
                                                   const std::vector<int32_t>& specialization) {
  const GridPassShaders shaders = grid_pass_shaders(variant);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_BLUR_SOURCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BLUR_SOURCE_UPPER, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_active_region_binding(variant, bindings);
  return engine::vk::GraphicsPipelineDesc{.name = "liquid.splat_spread_z",
                                          .vertex = shaders.vertex,
                                          .geometry = shaders.geometry,
                                          .fragment = variant.shader(shaders::splat_blur_z_frag),
                                          .color_formats = {format},
                                          .bindings = bindings,
                                          .specialization = specialization};
}

}  // namespace

SeparableSplatPass::SeparableSplatPass(engine::vk::Context& context, const SolverVariant& variant,
                                       VkFormat splat_format, const std::vector<int32_t>& specialization)
    : deposit_(context, deposit_pipeline(variant, splat_format, specialization)),
      spread_xy_(context, variant, SeparableBlur::Kind::Splat, splat_format, specialization),
      nearest_(context, VK_FILTER_NEAREST),
      scratch_desc_(variant.layout.image_desc(splat_format, 0)),
      variant_(variant) {
  if (variant.layout.dimension == 3) spread_z_.emplace(context, spread_z_pipeline(variant, splat_format, specialization));
  if (variant.active_region) active_region_.emplace(context, variant.layout, specialization);
}

void SeparableSplatPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                StepImages& step, int active) const {
  const Deposit d = deposit(graph, uniforms, step, active);
  step.region = active_region_ ? active_region_->add_to(graph, uniforms, d.lower) : ImageHandle{};
  step.splat = spread(graph, uniforms, d, step);
  step.deposit = d.lower;
  step.deposit_upper = d.upper;
}

SeparableSplatPass::Deposit SeparableSplatPass::deposit(engine::graph::RenderGraph& graph,
                                                        const engine::vk::UniformSlice& uniforms,
                                                        const StepImages& step, int active) const {
  const bool pair = spread_z_.has_value();
  const ImageHandle lower = graph.create_image("liquid.splat_deposit", scratch_desc_);
  const ImageHandle upper = pair ? graph.create_image("liquid.splat_upper", scratch_desc_) : ImageHandle{};
  return add_solver_pass<Deposit>(
      graph, deposit_, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        bind_particle_points(bindings, b, step.particles, nearest_);
        const engine::graph::AttachmentOptions clear = engine::graph::clear_to(0, 0, 0, 0);
        return Deposit{b.write(lower, Access::ColorAttachmentBlend, clear),
                       pair ? b.write(upper, Access::ColorAttachmentBlend, clear) : ImageHandle{}};
      },
      [active](const PassContext& ctx) {
        if (active > 0) vkCmdDraw(ctx.cmd, uint32_t(active), 1, 0, 0);
      });
}

ImageHandle SeparableSplatPass::spread(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                       const Deposit& deposit, const StepImages& step) const {
  // The deposit is kept for the particle pass's position correction. 2D: the x pass takes it to a
  // scratch image and the y pass to the splat. 3D: the z pass writes the splat from the deposit's
  // two grids, then x and y through a scratch image.
  const ImageHandle scratch = graph.create_image("liquid.splat_scratch", scratch_desc_);
  if (!spread_z_) {
    SeparableBlur::Targets targets{scratch, step.splat};
    return spread_xy_.add_to(graph, uniforms, deposit.lower, targets, step.region);
  }
  const ImageHandle splat = add_grid_cells_pass<ImageHandle>(
      graph, *spread_z_, uniforms, GridCells{variant_, step.region, nearest_},
      [&](engine::passes::PassBindings& bindings, PassBuilder& b, const engine::graph::AttachmentOptions& load) {
        bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE, deposit.lower, nearest_.handle());
        bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE_UPPER, deposit.upper, nearest_.handle());
        return b.write(step.splat, Access::ColorAttachmentWrite, load);
      });
  SeparableBlur::Targets targets{scratch, splat};
  return spread_xy_.add_to(graph, uniforms, splat, targets, step.region);
}

}  // namespace liquid
