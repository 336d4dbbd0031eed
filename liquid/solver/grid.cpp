#include "liquid/solver/grid.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/images.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

#include <stdexcept>

namespace liquid {

namespace {

std::span<const uint32_t> grid_fragment_shader(const SimulationSetup& setup, const GridLayout& layout, bool meshes) {
  using namespace liquid_shaders;
  if (setup.splat_adjoint_pressure)
    return mesh_variant(meshes, layout.pick(grid_adjoint_frag_2d, grid_adjoint_frag_3d, grid_adjoint_frag_3d_atlas),
                        layout.pick(grid_adjoint_frag_2d_mesh, grid_adjoint_frag_3d_mesh, grid_adjoint_frag_3d_atlas_mesh));
  return mesh_variant(meshes, layout.pick(grid_frag_2d, grid_frag_3d, grid_frag_3d_atlas),
                      layout.pick(grid_frag_2d_mesh, grid_frag_3d_mesh, grid_frag_3d_atlas_mesh));
}

std::vector<engine::vk::DescriptorBinding> grid_bindings(const SimulationSetup& setup, bool meshes,
                                                         bool active_region) {
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_GRID_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_body_shapes_binding(bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  if (setup.splat_adjoint_pressure)
    bindings.push_back({LIQUID_BINDING_GRID_POTENTIAL, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  add_mesh_field_binding(meshes, bindings);
  add_active_region_binding(active_region, bindings);
  return bindings;
}

}  // namespace

GridPass::GridPass(engine::vk::Context& context, const SimulationSetup& setup, const GridLayout& layout,
                   const std::vector<int32_t>& specialization, bool meshes, bool active_region)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.grid",
                    // 3D: every slice is a layer of the target (or a tile of the atlas).
                    .vertex = grid_pass_shaders(layout, active_region).vertex,
                    .geometry = grid_pass_shaders(layout, active_region).geometry,
                    .fragment = grid_fragment_shader(setup, layout, meshes),
                    .color_formats = {k_grid_velocity_format, k_density_format},
                    .bindings = grid_bindings(setup, meshes, active_region),
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      splat_adjoint_(setup.splat_adjoint_pressure),
      layout_(layout),
      active_region_(active_region) {}

GridImages GridPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                            ImageHandle splat, ImageHandle bodies, ImageHandle body_shapes, const GridImages& grids, ImageHandle potential,
                            ImageHandle mesh_field, ImageHandle region) const {
  if (splat_adjoint_ != potential.valid())
    throw std::logic_error(splat_adjoint_ ? "liquid.grid: the splat-adjoint pressure needs the potential image"
                                          : "liquid.grid: a potential image was given to the chapter's grid pass");
  struct Data {
    engine::passes::PassBindings bindings;
    GridImages out;
  };
  return graph
      .add_pass<Data>(
          "liquid.grid",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_GRID_SPLAT, splat, nearest_.handle());
            d.bindings.bind_image(b, LIQUID_BINDING_BODIES, bodies, nearest_.handle());
            bind_body_shapes(d.bindings, b, body_shapes, linear_);
            if (potential.valid()) d.bindings.bind_image(b, LIQUID_BINDING_GRID_POTENTIAL, potential, nearest_.handle());
            bind_mesh_field(d.bindings, b, mesh_field, nearest_);
            const engine::graph::AttachmentOptions load =
                bind_active_region(d.bindings, b, region, active_region_, nearest_);
            d.out.velocity = b.write(grids.velocity, Access::ColorAttachmentWrite, load);
            d.out.density = b.write(grids.density, Access::ColorAttachmentWrite, load);
          },
          [this](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            draw_grid_cells(ctx, layout_, active_region_);
          })
      .out;
}

}  // namespace liquid
