#include "liquid/solver/grid.h"

#include "liquid/solver/body_shapes.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/solver_pass.h"
#include "liquid/solver/state.h"
#include "liquid_shader_families.h"

namespace liquid {

namespace {

std::vector<engine::vk::DescriptorBinding> grid_bindings(const SolverVariant& variant) {
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_GRID_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_body_shapes_binding(bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  if (variant.splat_adjoint())
    bindings.push_back({LIQUID_BINDING_GRID_POTENTIAL, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  if (variant.projection())
    bindings.push_back({LIQUID_BINDING_GRID_PROJECTION_SYSTEM, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  add_mesh_field_binding(variant.meshes, bindings);
  add_active_region_binding(variant, bindings);
  return bindings;
}

// (u', fluid flag) and rho / rho0, and under the pressure projection the density correction.
std::vector<VkFormat> grid_formats(const SolverVariant& variant) {
  std::vector<VkFormat> formats{k_grid_velocity_format, k_density_format};
  if (variant.projection()) formats.push_back(k_density_correction_format);
  return formats;
}

}  // namespace

GridPass::GridPass(engine::vk::Context& context, const SolverVariant& variant,
                   const std::vector<int32_t>& specialization)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.grid",
                    // 3D: every slice is a layer of the target (or a tile of the atlas).
                    .vertex = grid_pass_shaders(variant).vertex,
                    .geometry = grid_pass_shaders(variant).geometry,
                    .fragment = variant.shader(shaders::grid_frag),
                    .color_formats = grid_formats(variant),
                    .bindings = grid_bindings(variant),
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      variant_(variant) {}

void GridPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                      StepImages& step) const {
  step.grids = add_grid_cells_pass<GridImages>(
      graph, pipeline_, uniforms, GridCells{variant_, step.region, nearest_},
      [&](engine::passes::PassBindings& bindings, PassBuilder& b, const engine::graph::AttachmentOptions& load) {
        bindings.bind_image(b, LIQUID_BINDING_GRID_SPLAT, step.splat, nearest_.handle());
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, nearest_.handle());
        bind_body_shapes(bindings, b, step.body_shapes, linear_);
        if (variant_.splat_adjoint())
          bindings.bind_image(b, LIQUID_BINDING_GRID_POTENTIAL, step.pressure.phi, nearest_.handle());
        if (variant_.projection())  // the cells' liquid fractions
          bindings.bind_image(b, LIQUID_BINDING_GRID_PROJECTION_SYSTEM, step.pressure.system, nearest_.handle());
        bind_mesh_field(bindings, b, step.mesh_field, nearest_);
        GridImages written{b.write(step.grids.velocity, Access::ColorAttachmentWrite, load),
                           b.write(step.grids.density, Access::ColorAttachmentWrite, load), {}};
        if (variant_.projection())
          written.correction = b.write(step.grids.correction, Access::ColorAttachmentWrite, load);
        return written;
      });
}

ImageHandle GridPass::create_correction(engine::graph::RenderGraph& graph) const {
  if (!variant_.projection()) return {};
  return graph.create_image("liquid.density_correction", variant_.layout.image_desc(k_density_correction_format, 0));
}

}  // namespace liquid
