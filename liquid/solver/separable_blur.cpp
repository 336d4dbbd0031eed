#include "liquid/solver/separable_blur.h"

#include "liquid/solver/solver_pass.h"
#include "liquid_shader_families.h"

#include <array>

namespace liquid {

namespace {

// The pass of `axis` (axis < the grid's dimension): its shader family and its name.
struct Axis {
  const ShaderFamily& family;
  const char* name;
};
Axis blur_axis(SeparableBlur::Kind kind, int axis) {
  static const std::array<Axis, 3> splat{Axis{shaders::splat_blur_x_frag, "liquid.splat_spread_x"},
                                         Axis{shaders::splat_blur_y_frag, "liquid.splat_spread_y"},
                                         Axis{shaders::splat_blur_z_frag, "liquid.splat_spread_z"}};
  static const std::array<Axis, 3> potential{Axis{shaders::potential_blur_x_frag, "liquid.potential_x"},
                                             Axis{shaders::potential_blur_y_frag, "liquid.potential_y"},
                                             Axis{shaders::potential_blur_z_frag, "liquid.potential_z"}};
  return (kind == SeparableBlur::Kind::Splat ? splat : potential)[size_t(axis)];
}

}  // namespace

SeparableBlur::SeparableBlur(engine::vk::Context& context, const SolverVariant& variant, Kind kind, VkFormat format,
                             const std::vector<int32_t>& specialization)
    : nearest_(context, VK_FILTER_NEAREST), variant_(variant) {
  const GridPassShaders shaders = grid_pass_shaders(variant);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_BLUR_SOURCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_active_region_binding(variant, bindings);
  // The splat's z pass reads the deposit's pair (SeparableSplatPass).
  const int axes = kind == Kind::Splat ? 2 : variant.layout.dimension;
  for (int axis = 0; axis < axes; ++axis) {
    const Axis a = blur_axis(kind, axis);
    axes_.emplace_back(context, engine::vk::GraphicsPipelineDesc{.name = a.name,
                                                                 .vertex = shaders.vertex,
                                                                 .geometry = shaders.geometry,
                                                                 .fragment = variant.shader(a.family),
                                                                 .color_formats = {format},
                                                                 .bindings = bindings,
                                                                 .specialization = specialization});
  }
}

ImageHandle SeparableBlur::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                  ImageHandle input, Targets& targets, ImageHandle region) const {
  ImageHandle* output = &targets.first;
  for (const engine::vk::GraphicsPipeline& pipeline : axes_) {
    *output = add_grid_cells_pass<ImageHandle>(
        graph, pipeline, uniforms, GridCells{variant_, region, nearest_},
        [&](engine::passes::PassBindings& bindings, PassBuilder& b, const engine::graph::AttachmentOptions& load) {
          bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE, input, nearest_.handle());
          return b.write(*output, Access::ColorAttachmentWrite, load);
        });
    input = *output;
    output = output == &targets.first ? &targets.second : &targets.first;
  }
  return input;
}

}  // namespace liquid
