#include "liquid/solver/separable_blur.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

#include <array>
#include <span>
#include <utility>

namespace liquid {

namespace {

using Shader = std::span<const uint32_t>;

// The variant for the layout and axis (axis < layout.dimension).
Shader blur_shader(const GridLayout& layout, SeparableBlur::Kind kind, int axis) {
  namespace s = liquid_shaders;
  const bool splat = kind == SeparableBlur::Kind::Splat;
  const std::array<Shader, 3> two_d = splat ? std::array<Shader, 3>{s::splat_blur_frag_2d_x, s::splat_blur_frag_2d_y, {}}
                                            : std::array<Shader, 3>{s::potential_blur_frag_2d_x, s::potential_blur_frag_2d_y, {}};
  const std::array<Shader, 3> three_d =
      splat ? std::array<Shader, 3>{s::splat_blur_frag_3d_x, s::splat_blur_frag_3d_y, s::splat_blur_frag_3d_z}
            : std::array<Shader, 3>{s::potential_blur_frag_3d_x, s::potential_blur_frag_3d_y, s::potential_blur_frag_3d_z};
  const std::array<Shader, 3> atlas =
      splat ? std::array<Shader, 3>{s::splat_blur_frag_3d_atlas_x, s::splat_blur_frag_3d_atlas_y,
                                    s::splat_blur_frag_3d_atlas_z}
            : std::array<Shader, 3>{s::potential_blur_frag_3d_atlas_x, s::potential_blur_frag_3d_atlas_y,
                                    s::potential_blur_frag_3d_atlas_z};
  return layout.pick(two_d[size_t(axis)], three_d[size_t(axis)], atlas[size_t(axis)]);
}

const char* pass_name(SeparableBlur::Kind kind, int axis) {
  static constexpr std::array<const char*, 3> splat{"liquid.splat_spread_x", "liquid.splat_spread_y",
                                                    "liquid.splat_spread_z"};
  static constexpr std::array<const char*, 3> potential{"liquid.potential_x", "liquid.potential_y",
                                                        "liquid.potential_z"};
  return (kind == SeparableBlur::Kind::Splat ? splat : potential)[size_t(axis)];
}

}  // namespace

SeparableBlur::SeparableBlur(engine::vk::Context& context, const GridLayout& layout, Kind kind, VkFormat format,
                             const std::vector<int32_t>& specialization, bool active_region)
    : nearest_(context, VK_FILTER_NEAREST), layout_(layout), active_region_(active_region) {
  const GridPassShaders shaders = grid_pass_shaders(layout, active_region);
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_BLUR_SOURCE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_active_region_binding(active_region, bindings);
  const int axes = kind == Kind::Splat ? 2 : layout.dimension;  // the splat's z pass reads the deposit's pair
  for (int axis = 0; axis < axes; ++axis)
    axes_.emplace_back(context, engine::vk::GraphicsPipelineDesc{.name = pass_name(kind, axis),
                                                                 .vertex = shaders.vertex,
                                                                 .geometry = shaders.geometry,
                                                                 .fragment = blur_shader(layout, kind, axis),
                                                                 .color_formats = {format},
                                                                 .bindings = bindings,
                                                                 .specialization = specialization});
}

ImageHandle SeparableBlur::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                  ImageHandle& source, ImageHandle& scratch, ImageHandle region) const {
  return chain(graph, uniforms, &source, &scratch, &source, region);
}

ImageHandle SeparableBlur::add_to_keeping(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                          ImageHandle source, ImageHandle& first, ImageHandle& second,
                                          ImageHandle region) const {
  return chain(graph, uniforms, &source, &first, &second, region);
}

ImageHandle SeparableBlur::chain(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                 ImageHandle* input, ImageHandle* first, ImageHandle* second, ImageHandle region) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle out;
  };
  ImageHandle* output = first;
  for (const engine::vk::GraphicsPipeline& pipeline : axes_) {
    *output =
        graph
            .add_pass<Data>(
                pipeline.name(),
                [&](PassBuilder& b, Data& d) {
                  d.bindings = engine::passes::PassBindings(pipeline);
                  d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
                  d.bindings.bind_image(b, LIQUID_BINDING_BLUR_SOURCE, *input, nearest_.handle());
                  d.out = b.write(*output, Access::ColorAttachmentWrite,
                                  bind_active_region(d.bindings, b, region, active_region_, nearest_));
                },
                [this](PassContext& ctx, const Data& d) {
                  d.bindings.bind_and_push(ctx);
                  draw_grid_cells(ctx, layout_, active_region_);
                })
            .out;
    input = output;
    output = output == first ? second : first;
  }
  return *input;
}

}  // namespace liquid
