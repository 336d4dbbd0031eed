#include "liquid/render/whitewater_draw.h"

#include "engine/passes/bindings.h"
#include "liquid/render/raymarch.h"
#include "liquid/solver/images.h"
#include "liquid/solver/node_view.h"
#include "liquid_shader_families.h"
#include "shaders/liquid/render/view_blocks.h"

namespace liquid {

namespace {

// Bubbles closer than this under the surface show through it, in particle spacings.
constexpr float k_bubble_lift_spacings = 3.0f;
// A sprite's radius, in particle spacings.
constexpr float k_sprite_radius_spacings = 0.35f;

}  // namespace

WhitewaterDraw::WhitewaterDraw(engine::vk::Context& context, const LiquidNode& node)
    : context_(context), node_(node), nearest_(context, VK_FILTER_NEAREST) {}

const engine::vk::GraphicsPipeline& WhitewaterDraw::pipeline(const Key& key) {
  auto& cached = pipelines_[key];
  if (!cached)
    cached = std::make_unique<engine::vk::GraphicsPipeline>(
        context_,
        engine::vk::GraphicsPipelineDesc{
            .name = "liquid.whitewater_draw",
            .vertex = shader_variant(shaders::whitewater_draw_vert),
            .fragment = shader_variant(shaders::whitewater_draw_frag),
            .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
            .color_formats = {key.color},
            .blend = {engine::vk::BlendMode::Alpha},
            .depth_format = key.depth,
            .depth_test = true,
            .depth_write = false,
            .depth_compare = key.reversed_z ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL,
            .bindings = {{LIQUID_BINDING_WHITEWATER_DRAW_POSITIONS, DescriptorKind::SampledImage,
                          VK_SHADER_STAGE_VERTEX_BIT}},
            .push_constant_size = sizeof(gpu::WhitewaterDrawPush),
            .specialization = {composite_output_encoding(key.color).value_or(LIQUID_OUTPUT_DISPLAY)}});
  return *cached;
}

WhitewaterDraw::Targets WhitewaterDraw::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                               Targets targets, const glm::mat4& view_projection, bool reversed_z,
                                               VkRect2D viewport, float exposure) {
  const engine::vk::ImageDesc& texture = graph.image_desc(images.whitewater_positions);
  const engine::vk::GraphicsPipeline& p =
      pipeline({graph.image_desc(targets.color).format, graph.image_desc(targets.depth).format, reversed_z});
  const SimulationSetup& setup = node_setup(node_);
  gpu::WhitewaterDrawPush push{};
  push.view_projection = view_projection;
  // Toward the camera: from a point halfway in clip depth to the near plane, through the view's centre.
  const glm::mat4 inverse = glm::inverse(view_projection);
  const glm::vec4 near_point = inverse * glm::vec4(0.0f, 0.0f, reversed_z ? 1.0f : 0.0f, 1.0f);
  const glm::vec4 mid_point = inverse * glm::vec4(0.0f, 0.0f, 0.5f, 1.0f);
  push.toward_camera = glm::normalize(glm::vec3(near_point) / near_point.w - glm::vec3(mid_point) / mid_point.w);
  push.bubble_lift = k_bubble_lift_spacings * setup.particle_spacing;
  push.radius = k_sprite_radius_spacings * setup.particle_spacing;
  // Clip y per metre across the view (the projection's focal scale, for any rigid view), in pixels.
  const glm::vec3 row_y(view_projection[0][1], view_projection[1][1], view_projection[2][1]);
  push.focal_pixels = glm::length(row_y) * 0.5f * float(viewport.extent.height);
  push.exposure = exposure;
  push.texture_width = int(texture.width);
  struct Data {
    engine::passes::PassBindings bindings;
    Targets out;
  };
  const uint32_t points = texture.width * texture.height;
  return graph
      .add_pass<Data>(
          "liquid.whitewater_draw",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(p);
            d.bindings.bind_image(b, LIQUID_BINDING_WHITEWATER_DRAW_POSITIONS, images.whitewater_positions,
                                  nearest_.handle());
            d.out.color = b.write(targets.color, Access::ColorAttachmentBlend);
            d.out.depth = b.write(targets.depth, Access::DepthAttachmentWrite, {engine::graph::LoadOp::Load, {}});
          },
          [&p, push, viewport, points](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            const VkViewport v{float(viewport.offset.x), float(viewport.offset.y), float(viewport.extent.width),
                               float(viewport.extent.height), 0.0f, 1.0f};
            vkCmdSetViewport(ctx.cmd, 0, 1, &v);
            vkCmdSetScissor(ctx.cmd, 0, 1, &viewport);
            p.push_constants(ctx.cmd, push);
            vkCmdDraw(ctx.cmd, points, 1, 0, 0);
          })
      .out;
}

}  // namespace liquid
