#include "liquid/solver/pressure.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/images.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

namespace {

// One full-screen pass over the grid (one layer per slice in 3D, or the atlas) with the solver's
// uniforms and one sampled grid at `binding`; P also reads the bodies (their kernel coverage).
engine::vk::GraphicsPipelineDesc grid_pipeline(const char* name, const GridLayout& layout,
                                               std::span<const uint32_t> fragment, uint32_t binding,
                                               const std::vector<int32_t>& specialization, bool bodies,
                                               bool meshes, bool active_region) {
  const GridPassShaders shaders = grid_pass_shaders(layout, active_region);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {binding, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  if (bodies) {
    bindings.push_back({LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
    add_body_shapes_binding(bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  }
  add_mesh_field_binding(meshes, bindings);
  add_active_region_binding(active_region, bindings);
  return engine::vk::GraphicsPipelineDesc{
      .name = name,
      .vertex = shaders.vertex,
      .geometry = shaders.geometry,
      .fragment = fragment,
      .color_formats = {k_pressure_format},
      .bindings = bindings,
      .specialization = specialization};
}

}  // namespace

PressurePass::PressurePass(engine::vk::Context& context, const GridLayout& layout, SplatMode splat,
                           const std::vector<int32_t>& specialization, bool meshes, bool active_region)
    : pressure_(context,
                grid_pipeline("liquid.pressure", layout,
                              mesh_variant(meshes,
                                           layout.pick(liquid_shaders::pressure_frag_2d, liquid_shaders::pressure_frag_3d,
                                                       liquid_shaders::pressure_frag_3d_atlas),
                                           layout.pick(liquid_shaders::pressure_frag_2d_mesh,
                                                       liquid_shaders::pressure_frag_3d_mesh,
                                                       liquid_shaders::pressure_frag_3d_atlas_mesh)),
                              LIQUID_BINDING_PRESSURE_SPLAT, specialization, true, meshes, active_region)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      desc_(layout.image_desc(k_pressure_format, 0)),
      layout_(layout),
      active_region_(active_region) {
  if (splat == SplatMode::Separable)
    spread_.emplace(context, layout, SeparableBlur::Kind::Potential, k_pressure_format, specialization, active_region);
  else
    potential_.emplace(context, grid_pipeline("liquid.potential", layout,
                                              layout.pick(liquid_shaders::potential_frag_2d,
                                                          liquid_shaders::potential_frag_3d,
                                                          liquid_shaders::potential_frag_3d_atlas),
                                              LIQUID_BINDING_POTENTIAL_PRESSURE, specialization, false, false,
                                              active_region));
}

ImageHandle PressurePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                 ImageHandle splat, ImageHandle bodies, ImageHandle body_shapes, ImageHandle& pressure,
                                 ImageHandle& potential, ImageHandle& scratch, ImageHandle mesh_field,
                                 ImageHandle region) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle out;
  };
  auto pass = [&](const char* name, const engine::vk::GraphicsPipeline& pipeline, uint32_t binding, ImageHandle input,
                  ImageHandle output, ImageHandle body_state, ImageHandle shapes, ImageHandle field) {
    return graph
        .add_pass<Data>(
            name,
            [&](PassBuilder& b, Data& d) {
              d.bindings = engine::passes::PassBindings(pipeline);
              d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
              d.bindings.bind_image(b, binding, input, nearest_.handle());
              if (body_state.valid()) {
                d.bindings.bind_image(b, LIQUID_BINDING_BODIES, body_state, nearest_.handle());
                bind_body_shapes(d.bindings, b, shapes, linear_);
              }
              bind_mesh_field(d.bindings, b, field, nearest_);
              d.out = b.write(output, Access::ColorAttachmentWrite,
                              bind_active_region(d.bindings, b, region, active_region_, nearest_));
            },
            [this](PassContext& ctx, const Data& d) {
              d.bindings.bind_and_push(ctx);
              draw_grid_cells(ctx, layout_, active_region_);
            })
        .out;
  };
  pressure = pass("liquid.pressure", pressure_, LIQUID_BINDING_PRESSURE_SPLAT, splat, pressure, bodies, body_shapes,
                  mesh_field);
  if (potential_) {
    potential = pass("liquid.potential", *potential_, LIQUID_BINDING_POTENTIAL_PRESSURE, pressure, potential, {}, {}, {});
    return potential;
  }
  if (scratch.valid()) return spread_->add_to_keeping(graph, uniforms, pressure, potential, scratch, region);
  return spread_->add_to(graph, uniforms, pressure, potential, region);
}

}  // namespace liquid
