#include "liquid/solver/active_region.h"

#include "engine/passes/fullscreen.h"
#include "liquid/solver/uniforms.h"
#include "liquid/solver/solver_pass.h"
#include "liquid_shader_families.h"

#include <cmath>
#include <stdexcept>

namespace liquid {

namespace {

constexpr VkFormat k_rows_format = VK_FORMAT_R32G32_SFLOAT;        // (first x, last x)
constexpr VkFormat k_rectangle_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // (x0, y0, x1, y1)
constexpr uint32_t k_rectangle_vertices = 6;                       // two triangles

engine::vk::GraphicsPipelineDesc reduction_pipeline(const char* name, std::span<const uint32_t> fragment,
                                                    uint32_t binding, VkFormat format,
                                                    const std::vector<int32_t>& specialization) {
  return engine::vk::GraphicsPipelineDesc{
      .name = name,
      .vertex = engine::passes::fullscreen_vertex_shader(),
      .fragment = fragment,
      .color_formats = {format},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {binding, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
      .specialization = specialization};
}

engine::vk::ImageDesc plain_image(uint32_t width, uint32_t height, VkFormat format) {
  return engine::vk::ImageDesc{engine::vk::ImageKind::Image2D, width, height, 1, format, 0};
}

}  // namespace

int active_region_bands(const GridLayout& layout) {
  return (layout.cells.y + LIQUID_ACTIVE_REGION_BAND_ROWS - 1) / LIQUID_ACTIVE_REGION_BAND_ROWS;
}

int active_region_margin_cells(const SimulationSetup& setup, bool projection) {
  const int r = int(std::ceil(setup.kernel_radius_cells));
  const int splat = setup.splat == SplatMode::Separable ? r + 1 : 0;
  return splat + (setup.splat_adjoint_pressure && !projection ? r + 2 : 1);
}

ActiveRegion::ActiveRegion(engine::vk::Context& context, const GridLayout& layout,
                           const std::vector<int32_t>& specialization)
    : rows_(context, reduction_pipeline("liquid.active_rows", shader_variant(shaders::active_rows_frag, layout),
                                        LIQUID_BINDING_ACTIVE_MARKS, k_rows_format, specialization)),
      slices_(context, reduction_pipeline("liquid.active_slices", shader_variant(shaders::active_slices_frag, layout),
                                          LIQUID_BINDING_ACTIVE_ROWS, k_rectangle_format, specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      rows_desc_(plain_image(uint32_t(layout.cells.y), uint32_t(layout.cells.z), k_rows_format)),
      slices_desc_(plain_image(uint32_t(active_region_bands(layout)), uint32_t(layout.cells.z), k_rectangle_format)) {}

ImageHandle ActiveRegion::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                 ImageHandle marks) const {
  auto reduce = [&](const engine::vk::GraphicsPipeline& pipeline, uint32_t binding, ImageHandle input,
                    const engine::vk::ImageDesc& desc) {
    const ImageHandle target = graph.create_image(pipeline.name(), desc);
    return add_solver_pass<ImageHandle>(
        graph, pipeline, uniforms,
        [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
          bindings.bind_image(b, binding, input, nearest_.handle());
          return b.write(target, Access::ColorAttachmentWrite);
        },
        [](const PassContext& ctx) { engine::passes::draw_fullscreen(ctx.cmd); });
  };
  const ImageHandle rows = reduce(rows_, LIQUID_BINDING_ACTIVE_MARKS, marks, rows_desc_);
  return reduce(slices_, LIQUID_BINDING_ACTIVE_ROWS, rows, slices_desc_);
}

void add_active_region_binding(const SolverVariant& variant, std::vector<engine::vk::DescriptorBinding>& bindings) {
  if (variant.active_region)
    bindings.push_back({LIQUID_BINDING_ACTIVE_REGION, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT});
}

engine::graph::AttachmentOptions bind_active_region(engine::passes::PassBindings& bindings, PassBuilder& builder,
                                                    ImageHandle region, bool active_region,
                                                    const engine::vk::Sampler& nearest) {
  if (region.valid() != active_region)
    throw std::logic_error(active_region ? "liquid: a grid pass made for the active region was given none"
                                         : "liquid: an active region was given to a whole-grid pass");
  if (!region.valid()) return {};
  bindings.bind_image(builder, LIQUID_BINDING_ACTIVE_REGION, region, nearest.handle());
  return engine::graph::clear_to(0.0f, 0.0f, 0.0f, 0.0f);
}

void draw_grid_cells(const PassContext& ctx, const GridLayout& layout, bool active_region) {
  if (!active_region) {
    engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
    return;
  }
  // An instance per band of each slice.
  vkCmdDraw(ctx.cmd, k_rectangle_vertices, uint32_t(active_region_bands(layout) * layout.cells.z), 0, 0);
}

}  // namespace liquid
