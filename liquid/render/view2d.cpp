#include "liquid/render/view2d.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/solver/images.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/node_view.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shader_families.h"
#include "shaders/liquid/render/view_blocks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace liquid {

namespace {

// How far up (cells) the depth pass looks for the surface; depth below this is the deepest blue.
constexpr float k_depth_search_cells = 24.0f;

// R16F: linear filtering is guaranteed for it, and 0 to 24 cells need no more precision.
constexpr VkFormat k_view2d_depth_format = VK_FORMAT_R16_SFLOAT;

using gpu::Particles2dPush;
using gpu::View2dPush;
static_assert(sizeof(View2dPush) == 32 && sizeof(Particles2dPush) == 32);

// The scene's constants plus the view's own (LIQUID_VIEW2D_PANEL_ID).
std::vector<int32_t> view2d_specialization(const LiquidNode& node, bool panel) {
  static_assert(LIQUID_VIEW2D_PANEL_ID == specialization_id::count, "the view's constant follows the scene's");
  std::vector<int32_t> constants = scene_specialization(node.scene(), node_setup(node));
  constants.push_back(panel ? 1 : 0);
  return constants;
}

const LiquidNode& require_2d(const LiquidNode& node) {
  if (node.dimension() != 2) throw UsageError("liquid: the 2D view needs a two-dimensional scene");
  return node;
}

std::vector<engine::vk::DescriptorBinding> view2d_bindings(bool meshes) {
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_VIEW2D_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_VIEW2D_DEPTH, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  add_mesh_field_binding(meshes, bindings);
  return bindings;
}

}  // namespace

View2dLayout fit_view2d(glm::vec2 domain, uint32_t width, uint32_t height) {
  const glm::vec2 frame{float(width), float(height)};
  View2dLayout layout;
  layout.wall_pixels = std::max(2.0f, 0.012f * std::min(frame.x, frame.y));
  // Walls plus a gap of the same size on every side.
  const glm::vec2 room = glm::max(frame - 4.0f * layout.wall_pixels, glm::vec2(1.0f));
  layout.pixels_per_metre = std::min(room.x / domain.x, room.y / domain.y);
  const glm::vec2 size = domain * layout.pixels_per_metre;
  // Whole pixels, so that the domain's edges fall on pixel boundaries.
  layout.origin = glm::vec2(std::round(0.5f * (frame.x - size.x)), std::round(0.5f * (frame.y + size.y)));
  return layout;
}

namespace {

// The liquid's pipeline: the whole frame opaque, or a panel blended over the host's pixels (PANEL:
// the liquid and obstacles alone, with their coverage in alpha; `opaque_in_panel`: the whole view,
// background and walls too, drawn into the host's rectangle with alpha 1).
engine::vk::GraphicsPipelineDesc view2d_pipeline_desc(const LiquidNode& node, bool panel, bool opaque_in_panel = false) {
  const bool blended = panel || opaque_in_panel;
  return engine::vk::GraphicsPipelineDesc{
      .name = opaque_in_panel ? "liquid.view2d.opaque_panel" : "liquid.view2d",
      .vertex = engine::passes::fullscreen_vertex_shader(),
      .fragment = shader_variant(shaders::view2d_frag, has_mesh_obstacles(node.scene()) ? shader_feature::MESH_FIELD : 0u),
      .color_formats = {k_color_format},
      .blend = {blended ? engine::vk::BlendMode::Alpha : engine::vk::BlendMode::None},
      .bindings = view2d_bindings(has_mesh_obstacles(node.scene())),
      .push_constant_size = sizeof(View2dPush),
      .specialization = view2d_specialization(node, panel)};
}


// Points from a particle texture (particles2d.vert or whitewater2d.vert), alpha-blended.
engine::vk::GraphicsPipelineDesc points_pipeline_desc(const char* name, const ShaderFamily& vertex,
                                                      const ShaderFamily& fragment) {
  return {.name = name,
          .vertex = shader_variant(vertex),
          .fragment = shader_variant(fragment),
          .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
          .color_formats = {k_color_format},
          .blend = {engine::vk::BlendMode::Alpha},
          .bindings = {{LIQUID_BINDING_PARTICLES2D_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
          .push_constant_size = sizeof(Particles2dPush)};
}

}  // namespace

View2dPass::View2dPass(engine::vk::Context& context, const LiquidNode& node, ViewOutput output)
    : node_(require_2d(node)),
      depth_(context, engine::vk::GraphicsPipelineDesc{
                          .name = "liquid.view2d.depth",
                          .vertex = engine::passes::fullscreen_vertex_shader(),
                          .fragment = shader_variant(shaders::view2d_depth_frag),
                          .color_formats = {k_view2d_depth_format},
                          .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                                       {LIQUID_BINDING_VIEW2D_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                          .push_constant_size = sizeof(View2dPush),
                          .specialization = scene_specialization(node.scene(), node_setup(node))}),
      liquid_(context, view2d_pipeline_desc(node, output == ViewOutput::HostTargets)),
      opaque_panel_(output == ViewOutput::HostTargets
                        ? engine::vk::GraphicsPipeline(context, view2d_pipeline_desc(node, false, true))
                          : engine::vk::GraphicsPipeline()),
      particles_(context, points_pipeline_desc("liquid.view2d.particles", shaders::particles2d_vert,
                                               shaders::particles2d_frag)),
      whitewater_(node.scene().whitewater
                      ? engine::vk::GraphicsPipeline(context,
                                                     points_pipeline_desc("liquid.view2d.whitewater",
                                                                          shaders::whitewater2d_vert,
                                                                          shaders::whitewater2d_frag))
                      : engine::vk::GraphicsPipeline()),
      linear_(context, VK_FILTER_LINEAR),
      nearest_(context, VK_FILTER_NEAREST),
      uniforms_(context, node, 0) {}

ImageHandle View2dPass::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                               const RenderSettings& settings, const HostPanel* panel) {
  const SimulationSetup& setup = node_setup(node_);
  const engine::vk::UniformSlice solver = uniforms_.begin_frame();

  // The domain fitted into the frame, or into the host's rectangle (then moved to its place).
  const VkRect2D area = panel ? panel->rect : VkRect2D{{0, 0}, {settings.width, settings.height}};
  View2dLayout layout = fit_view2d(glm::vec2(setup.domain), area.extent.width, area.extent.height);
  layout.origin += glm::vec2(area.offset.x, area.offset.y);
  const glm::vec2 frame{float(settings.width), float(settings.height)};
  const View2dPush push{layout.origin, layout.pixels_per_metre, settings.iso_level,
                        frame,         layout.wall_pixels,      k_depth_search_cells};

  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle color;
  };
  const ImageHandle density = images.density;
  const engine::vk::ImageDesc color_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_color_format, 0};
  const engine::vk::ImageDesc depth_desc{engine::vk::ImageKind::Image2D, uint32_t(setup.grid_cells.x),
                                         uint32_t(setup.grid_cells.y), 1, k_view2d_depth_format, 0};
  const ImageHandle depth =
      graph
          .add_pass<Data>(
              "liquid.view2d.depth",
              [&](PassBuilder& b, Data& d) {
                d.bindings = engine::passes::PassBindings(depth_);
                d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
                d.bindings.bind_image(b, LIQUID_BINDING_VIEW2D_DENSITY, density, nearest_.handle());
                d.color = b.write(b.create("liquid.view2d.depth", depth_desc), Access::ColorAttachmentWrite);
              },
              [this, push](PassContext& ctx, const Data& d) {
                d.bindings.bind_and_push(ctx);
                depth_.push_constants(ctx.cmd, push);
                engine::passes::draw_fullscreen(ctx.cmd);
              })
          .color;
  const engine::vk::GraphicsPipeline* pipeline = panel && panel->background ? &opaque_panel_ : &liquid_;
  ImageHandle color =
      graph
          .add_pass<Data>(
              "liquid.view2d",
              [&](PassBuilder& b, Data& d) {
                d.bindings = engine::passes::PassBindings(*pipeline);
                d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
                d.bindings.bind_image(b, LIQUID_BINDING_VIEW2D_DENSITY, density, linear_.handle());
                d.bindings.bind_image(b, LIQUID_BINDING_VIEW2D_DEPTH, depth, linear_.handle());
                bind_mesh_field(d.bindings, b, images.mesh_field, linear_);
                d.color = panel ? b.write(panel->color, Access::ColorAttachmentBlend)
                                : b.write(b.create("liquid.view2d", color_desc), Access::ColorAttachmentWrite);
              },
              [pipeline, push, area](PassContext& ctx, const Data& d) {
                d.bindings.bind_and_push(ctx);
                pipeline->push_constants(ctx.cmd, push);
                vkCmdSetScissor(ctx.cmd, 0, 1, &area);
                engine::passes::draw_fullscreen(ctx.cmd);
              })
          .color;
  // Particles: points blended over the liquid, about 0.7 particle spacings wide (1 to 5 pixels).
  // Where the particles are packed closer than a few pixels, each point is fainter, so that the
  // liquid still shows through instead of a white sheet.
  const float spacing_pixels = setup.particle_spacing * layout.pixels_per_metre;
  if (settings.draw_particles && node_.active_particles() > 0) {
    const Particles2dPush push{layout.origin, layout.pixels_per_metre, std::clamp(0.7f * spacing_pixels, 1.0f, 5.0f),
                               frame, setup.particle_texture.x, std::clamp(spacing_pixels / 3.0f, 0.25f, 0.85f)};
    color = draw_points(graph, particles_, images.positions, color, push, uint32_t(node_.active_particles()));
  }
  // The secondary particles over them: every slot (the free ones are clipped), a little smaller.
  if (settings.whitewater && whitewater_.handle() != VK_NULL_HANDLE && images.whitewater_positions.valid()) {
    const engine::vk::ImageDesc& texture = graph.image_desc(images.whitewater_positions);
    const Particles2dPush push{layout.origin, layout.pixels_per_metre, std::clamp(0.6f * spacing_pixels, 1.5f, 4.0f),
                               frame, int(texture.width), 0.9f};
    color = draw_points(graph, whitewater_, images.whitewater_positions, color, push, texture.width * texture.height);
  }
  return color;
}

ImageHandle View2dPass::draw_points(engine::graph::RenderGraph& graph, const engine::vk::GraphicsPipeline& pipeline,
                                    ImageHandle positions, ImageHandle color, const gpu::Particles2dPush& push,
                                    uint32_t count) const {
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle color;
  };
  return graph
      .add_pass<Data>(
          pipeline.name(),
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline);
            d.bindings.bind_image(b, LIQUID_BINDING_PARTICLES2D_POSITIONS, positions, nearest_.handle());
            d.color = b.write(color, Access::ColorAttachmentBlend);
          },
          [&pipeline, push, count](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            pipeline.push_constants(ctx.cmd, push);
            vkCmdDraw(ctx.cmd, count, 1, 0, 0);
          })
      .color;
}

}  // namespace liquid
