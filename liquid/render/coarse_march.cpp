#include "liquid/render/coarse_march.h"

#include "engine/passes/fullscreen.h"
#include "liquid/solver/node_view.h"
#include "liquid/solver/specialization.h"
#include "liquid_shader_families.h"
#include "shaders/liquid/render/view_blocks.h"

#include <algorithm>

namespace liquid {

namespace {

using engine::graph::Access;
using engine::graph::ImageHandle;
using engine::graph::PassBuilder;
using engine::graph::PassContext;
using engine::vk::DescriptorKind;

constexpr VkFormat k_crossing_format = VK_FORMAT_R32_SFLOAT;  // the coarse rays' distances, m
constexpr VkFormat k_tile_format = VK_FORMAT_R8_UINT;         // LIQUID_RAYMARCH_TILE_MISS or _LIQUID

// The coarse march (raymarch_coarse.frag): one ray per LIQUID_RAYMARCH_COARSE_PIXELS^2 pixels.
engine::vk::GraphicsPipelineDesc coarse_pipeline_desc(const LiquidNode& node, const GridLayout& bricks) {
  return engine::vk::GraphicsPipelineDesc{
      .name = "liquid.raymarch_coarse",
      .vertex = engine::passes::fullscreen_vertex_shader(),
      .fragment = shader_variant(shaders::raymarch_coarse_frag, bricks.atlas() ? shader_feature::ATLAS : 0u),
      .color_formats = {k_crossing_format},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_OCCUPANCY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
      .specialization = scene_specialization(node.scene(), node_setup(node))};
}

// The screen tiles' kinds (raymarch_tiles.frag).
engine::vk::GraphicsPipelineDesc tiles_pipeline_desc() {
  return engine::vk::GraphicsPipelineDesc{
      .name = "liquid.raymarch_tiles",
      .vertex = engine::passes::fullscreen_vertex_shader(),
      .fragment = shader_variant(shaders::raymarch_tiles_frag),
      .color_formats = {k_tile_format},
      .bindings = {{LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_COARSE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}}};
}

// The pixels (half-open, clamped to the frame) that rays into the domain box can cover: the bounds
// of its eight corners projected, a pixel wider each side for rounding; the whole frame when a
// corner lies behind the camera. The pixel at (x, y) shows the ray through NDC 2 (x + 0.5) / width - 1
// (fullscreen.vert and raymarch.frag).
VkRect2D domain_screen_rect(const glm::mat4& view_projection, glm::vec3 domain, VkRect2D viewport) {
  const VkRect2D frame = viewport;
  const uint32_t width = viewport.extent.width, height = viewport.extent.height;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p = domain * glm::vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f) return frame;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  const glm::vec2 size{float(width), float(height)};
  const glm::vec2 first = glm::clamp(glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f, glm::vec2(0.0f), size);
  const glm::vec2 end = glm::clamp(glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f, glm::vec2(0.0f), size);
  if (end.x <= first.x || end.y <= first.y) return {{0, 0}, {0, 0}};
  return {{viewport.offset.x + int32_t(first.x), viewport.offset.y + int32_t(first.y)},
          {uint32_t(end.x - first.x), uint32_t(end.y - first.y)}};
}

// `extent` pixels in whole blocks of `block` pixels.
uint32_t blocks(uint32_t extent, uint32_t block) { return (extent + block - 1) / block; }

// The coarse rays (raymarch_tiles.glsl) that the pixels of `rect` (in the view's pixels) read, as a
// rectangle of the coarse image of `size`.
VkRect2D coarse_rect(VkRect2D rect, VkExtent2D size) {
  constexpr int k = LIQUID_RAYMARCH_COARSE_PIXELS;
  const int x0 = std::max(0, rect.offset.x / k - 1), y0 = std::max(0, rect.offset.y / k - 1);
  const int x1 = std::min(int(size.width), (rect.offset.x + int(rect.extent.width)) / k + 2);
  const int y1 = std::min(int(size.height), (rect.offset.y + int(rect.extent.height)) / k + 2);
  if (x1 <= x0 || y1 <= y0) return {{0, 0}, {0, 0}};
  return {{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
}

}  // namespace

CoarseMarch::CoarseMarch(engine::vk::Context& context, const LiquidNode& node, const GridLayout& bricks)
    : coarse_(context, coarse_pipeline_desc(node, bricks)), tiles_(context, tiles_pipeline_desc()) {}

CoarseMarch::Sizes CoarseMarch::sizes(VkExtent2D view) {
  // One coarse ray per LIQUID_RAYMARCH_COARSE_PIXELS^2 pixels, and one beyond each edge (the pixels
  // of the last row and column read the rays on both sides of them).
  return {{view.width / LIQUID_RAYMARCH_COARSE_PIXELS + 2, view.height / LIQUID_RAYMARCH_COARSE_PIXELS + 2},
          {blocks(view.width, LIQUID_RAYMARCH_TILE_PIXELS), blocks(view.height, LIQUID_RAYMARCH_TILE_PIXELS)}};
}

CoarseMarch::Outputs CoarseMarch::add_to(engine::graph::RenderGraph& graph, const BindMarch& bind_march,
                                         const engine::vk::UniformSlice& view_uniforms, VkSampler nearest,
                                         const glm::mat4& view_projection, glm::vec3 domain, VkRect2D viewport) const {
  const Sizes size = sizes(viewport.extent);
  // The coarse march, only over the rays that can reach the domain box; the others keep the clear
  // value, no crossing.
  struct CoarseData {
    engine::passes::PassBindings bindings;
    VkRect2D rays{};
    ImageHandle crossings;
  };
  const ImageHandle crossings =
      graph
          .add_pass<CoarseData>(
              "liquid.raymarch_coarse",
              [&](PassBuilder& b, CoarseData& d) {
                d.bindings = bind_march(b, coarse_);
                VkRect2D box = domain_screen_rect(view_projection, domain, viewport);
                box.offset.x -= viewport.offset.x;  // in the view's pixels
                box.offset.y -= viewport.offset.y;
                d.rays = coarse_rect(box, size.rays);
                const float no_crossing = float(LIQUID_RAYMARCH_NO_CROSSING);
                d.crossings = b.write(b.create("liquid.raymarch_crossings", {engine::vk::ImageKind::Image2D, size.rays.width,
                                                                             size.rays.height, 1, k_crossing_format, 0}),
                                      Access::ColorAttachmentWrite, engine::graph::clear_to(no_crossing, 0.0f, 0.0f, 0.0f));
              },
              [](PassContext& ctx, const CoarseData& d) {
                if (d.rays.extent.width == 0 || d.rays.extent.height == 0) return;
                d.bindings.bind_and_push(ctx);
                vkCmdSetScissor(ctx.cmd, 0, 1, &d.rays);
                engine::passes::draw_fullscreen(ctx.cmd);
              })
          .crossings;

  // Each screen tile's kind: whether any coarse ray its pixels read met the liquid.
  struct TilesData {
    engine::passes::PassBindings bindings;
    ImageHandle kinds;
  };
  const ImageHandle kinds =
      graph
          .add_pass<TilesData>(
              "liquid.raymarch_tiles",
              [&](PassBuilder& b, TilesData& d) {
                d.bindings = engine::passes::PassBindings(tiles_);
                d.bindings.bind_uniform(LIQUID_BINDING_VIEW_UNIFORMS, view_uniforms);
                d.bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_COARSE, crossings, nearest);
                d.kinds = b.write(b.create("liquid.raymarch_tiles", {engine::vk::ImageKind::Image2D, size.tiles.width,
                                                                     size.tiles.height, 1, k_tile_format, 0}),
                                  Access::ColorAttachmentWrite);
              },
              [](PassContext& ctx, const TilesData& d) {
                d.bindings.bind_and_push(ctx);
                engine::passes::draw_fullscreen(ctx.cmd);
              })
          .kinds;
  return {crossings, kinds};
}

}  // namespace liquid
