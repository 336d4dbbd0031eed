#include "liquid/solver/pressure.h"

#include "engine/graph/transfer.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/solver_pass.h"
#include "liquid_shader_families.h"

namespace liquid {

namespace {

// A full-screen pass over the grid with the solver's uniforms and one sampled grid at `binding`,
// writing a pressure-format grid.
engine::vk::GraphicsPipelineDesc grid_pipeline(const char* name, const SolverVariant& variant,
                                               std::span<const uint32_t> fragment, uint32_t binding,
                                               const std::vector<int32_t>& specialization) {
  const GridPassShaders shaders = grid_pass_shaders(variant);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {binding, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_active_region_binding(variant, bindings);
  return engine::vk::GraphicsPipelineDesc{
      .name = name,
      .vertex = shaders.vertex,
      .geometry = shaders.geometry,
      .fragment = fragment,
      .color_formats = {k_pressure_format},
      .bindings = bindings,
      .specialization = specialization};
}

// A pass that also reads the bodies (their kernel coverage, or their solid cells) and the mesh field.
engine::vk::GraphicsPipelineDesc obstacle_grid_pipeline(const char* name, const SolverVariant& variant,
                                                        std::span<const uint32_t> fragment,
                                                        const std::vector<int32_t>& specialization) {
  engine::vk::GraphicsPipelineDesc desc = grid_pipeline(name, variant, fragment, LIQUID_BINDING_PRESSURE_SPLAT, specialization);
  desc.bindings.push_back({LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  add_body_shapes_binding(desc.bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  add_mesh_field_binding(variant.meshes, desc.bindings);
  return desc;
}

}  // namespace

PressurePass::PressurePass(engine::vk::Context& context, const SolverVariant& variant,
                           const std::vector<int32_t>& specialization)
    : pressure_(context, obstacle_grid_pipeline("liquid.pressure", variant, variant.shader(shaders::pressure_frag),
                                                specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      variant_(variant) {
  if (variant.projection()) {
    engine::vk::GraphicsPipelineDesc divergence = obstacle_grid_pipeline(
        "liquid.projection_divergence", variant, variant.shader(shaders::projection_divergence_frag), specialization);
    // The row pass also takes the first Jacobi iteration, from the last step's p.
    divergence.bindings.push_back({LIQUID_BINDING_PROJECTION_PRESSURE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
    divergence.color_formats = {k_projection_system_format, k_projection_pressure_format};
    divergence_.emplace(context, divergence);
    engine::vk::GraphicsPipelineDesc jacobi = grid_pipeline(
        "liquid.projection_jacobi", variant, variant.shader(shaders::projection_jacobi_frag),
        LIQUID_BINDING_PROJECTION_PRESSURE, specialization);
    jacobi.bindings.push_back({LIQUID_BINDING_PROJECTION_SYSTEM, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
    jacobi.color_formats = {k_projection_pressure_format};
    jacobi_.emplace(context, jacobi);
    constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    const engine::vk::ImageDesc desc = variant.layout.image_desc(k_projection_pressure_format, usage);
    projection_pressure_.emplace(context, desc, "liquid.projection_pressure");
    const std::vector<std::byte> zeros(size_t(desc.width) * desc.height * desc.depth_or_layers *
                                       engine::vk::format_texel_size(desc.format));
    engine::graph::upload_image(context, *projection_pressure_, zeros);
    return;
  }
  if (variant.splat == SplatMode::Separable)
    spread_.emplace(context, variant, SeparableBlur::Kind::Potential, k_pressure_format, specialization);
  else
    potential_.emplace(context, grid_pipeline("liquid.potential", variant, variant.shader(shaders::potential_frag),
                                              LIQUID_BINDING_POTENTIAL_PRESSURE, specialization));
}

PressureImages PressurePass::create_images(engine::graph::RenderGraph& graph) const {
  // Under the projection the two are its Jacobi iterations' ping-pong.
  const engine::vk::ImageDesc desc =
      variant_.layout.image_desc(projection_pressure_ ? k_projection_pressure_format : k_pressure_format, 0);
  PressureImages images{graph.create_image("liquid.pressure", desc), graph.create_image("liquid.potential", desc), {}, {}, {}};
  // The body force reads P after the spread.
  if (variant_.pressure_scratch()) images.scratch = graph.create_image("liquid.potential_scratch", desc);
  if (projection_pressure_) {
    images.phi = graph.import_image(projection_pressure_->name(), *projection_pressure_);
    images.system = graph.create_image("liquid.projection_system",
                                       variant_.layout.image_desc(k_projection_system_format, 0));
  }
  return images;
}

void PressurePass::add_projection_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                     StepImages& step, bool stepping) const {
  PressureImages& p = step.pressure;
  const GridCells cells{variant_, step.region, nearest_};
  using engine::graph::AttachmentOptions;
  // The rows into `system` and the first iteration from p.phi (the last step's p) into `pressure`;
  // then the other iterations through `potential` and `pressure` in turn, the last one writing p.phi
  // again. Without a step only the cells' liquid fractions are needed (the grid pass reads them), and
  // p.phi stays the last step's p.
  struct Rows {
    ImageHandle system, first_iterate;
  };
  const Rows rows = add_grid_cells_pass<Rows>(
      graph, *divergence_, uniforms, cells,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b, const AttachmentOptions& load) {
        bindings.bind_image(b, LIQUID_BINDING_PRESSURE_SPLAT, step.splat, nearest_.handle());
        bindings.bind_image(b, LIQUID_BINDING_PROJECTION_PRESSURE, p.phi, nearest_.handle());
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, nearest_.handle());
        bind_body_shapes(bindings, b, step.body_shapes, linear_);
        bind_mesh_field(bindings, b, step.mesh_field, nearest_);
        return Rows{b.write(p.system, Access::ColorAttachmentWrite, load),
                    b.write(p.pressure, Access::ColorAttachmentWrite, load)};
      });
  p.system = rows.system;
  p.pressure = rows.first_iterate;
  if (!stepping) return;
  ImageHandle source = p.pressure;
  for (int i = 1; i < variant_.projection_iterations; ++i) {  // the scene allows no fewer than 2
    const bool last = i + 1 == variant_.projection_iterations;
    ImageHandle& target = last ? p.phi : (i % 2 == 1 ? p.potential : p.pressure);
    target = add_grid_cells_pass<ImageHandle>(
        graph, *jacobi_, uniforms, cells,
        [&](engine::passes::PassBindings& bindings, PassBuilder& b, const AttachmentOptions& load) {
          bindings.bind_image(b, LIQUID_BINDING_PROJECTION_PRESSURE, source, nearest_.handle());
          bindings.bind_image(b, LIQUID_BINDING_PROJECTION_SYSTEM, p.system, nearest_.handle());
          return b.write(target, Access::ColorAttachmentWrite, load);
        });
    source = target;
  }
}

void PressurePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                          StepImages& step, bool stepping) const {
  if (projection_pressure_) {
    add_projection_to(graph, uniforms, step, stepping);
    return;
  }
  PressureImages& p = step.pressure;
  const GridCells cells{variant_, step.region, nearest_};
  using engine::graph::AttachmentOptions;
  p.pressure = add_grid_cells_pass<ImageHandle>(
      graph, pressure_, uniforms, cells,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b, const AttachmentOptions& load) {
        bindings.bind_image(b, LIQUID_BINDING_PRESSURE_SPLAT, step.splat, nearest_.handle());
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, nearest_.handle());
        bind_body_shapes(bindings, b, step.body_shapes, linear_);
        bind_mesh_field(bindings, b, step.mesh_field, nearest_);
        return b.write(p.pressure, Access::ColorAttachmentWrite, load);
      });
  if (potential_) {
    p.potential = add_grid_cells_pass<ImageHandle>(
        graph, *potential_, uniforms, cells,
        [&](engine::passes::PassBindings& bindings, PassBuilder& b, const AttachmentOptions& load) {
          bindings.bind_image(b, LIQUID_BINDING_POTENTIAL_PRESSURE, p.pressure, nearest_.handle());
          return b.write(p.potential, Access::ColorAttachmentWrite, load);
        });
    p.phi = p.potential;
    return;
  }
  // The spread from P: through the potential's image and P's own, or the scratch image instead of P's.
  SeparableBlur::Targets targets{p.potential, p.scratch.valid() ? p.scratch : p.pressure};
  p.phi = spread_->add_to(graph, uniforms, p.pressure, targets, step.region);
  p.potential = targets.first;
  (p.scratch.valid() ? p.scratch : p.pressure) = targets.second;
}

}  // namespace liquid
