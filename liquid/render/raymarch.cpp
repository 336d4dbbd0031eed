#include "liquid/render/raymarch.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "engine/vk/context.h"
#include "liquid/solver/images.h"
#include "liquid/solver/node_view.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shader_families.h"
#include "shaders/liquid/render/view_blocks.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace liquid {

namespace {

constexpr float k_fine_step_cells = 0.6f;

// The scene's constants plus the raymarch's own (LIQUID_RAYMARCH_COMPOSITE_ID, then
// LIQUID_RAYMARCH_BACKGROUND_ONLY_ID and LIQUID_RAYMARCH_OUTPUT_ID).
std::vector<int32_t> raymarch_specialization(const LiquidNode& node, bool composite, bool background_only,
                                             int output) {
  static_assert(LIQUID_RAYMARCH_COMPOSITE_ID == specialization_id::count, "the raymarch's constants follow the scene's");
  static_assert(LIQUID_RAYMARCH_BACKGROUND_ONLY_ID == LIQUID_RAYMARCH_COMPOSITE_ID + 1);
  static_assert(LIQUID_RAYMARCH_OUTPUT_ID == LIQUID_RAYMARCH_BACKGROUND_ONLY_ID + 1);
  std::vector<int32_t> constants = scene_specialization(node.scene(), node_setup(node));
  constants.push_back(composite ? 1 : 0);
  constants.push_back(background_only ? 1 : 0);
  constants.push_back(output);
  return constants;
}

engine::vk::GraphicsPipelineDesc raymarch_pipeline_desc(const LiquidNode& node, const GridLayout& bricks,
                                                       bool composite, bool background_only, bool reversed_z = false,
                                                       VkFormat color_format = k_color_format,
                                                       VkFormat depth_format = k_depth_format) {
  // Composited: blended over the host's colour (the shader writes the liquid's coverage in alpha),
  // filtering it per channel where the device has dual-source blending.
  const bool transmit = composite && node.context().supports_dual_source_blend();
  const auto fragment = shader_variant(shaders::raymarch_frag, (bricks.atlas() ? shader_feature::ATLAS : 0u) |
                                                                    (transmit ? shader_feature::TRANSMIT : 0u));
  return engine::vk::GraphicsPipelineDesc{
      .name = background_only ? "liquid.raymarch.background" : "liquid.raymarch",
      .vertex = shader_variant(shaders::raymarch_tile_vert),
      .fragment = fragment,
      .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
      .color_formats = {color_format},
      .blend = {transmit    ? engine::vk::BlendMode::Transmit
                : composite ? engine::vk::BlendMode::Alpha
                            : engine::vk::BlendMode::None},
      .depth_format = depth_format,
      .depth_test = true,
      .depth_write = true,
      .depth_compare = reversed_z ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL,
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer,
                    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_OCCUPANCY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_COARSE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_RAYMARCH_TILES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .specialization = raymarch_specialization(node, composite, background_only,
                                                composite ? composite_output_encoding(color_format).value_or(0) : 0)};
}

// The tank's frame (tank_frame.vert, .frag), drawn over the raymarched frame, depth-tested against it.
engine::vk::GraphicsPipelineDesc tank_frame_pipeline_desc() {
  return engine::vk::GraphicsPipelineDesc{
      .name = "liquid.tank_frame",
      .vertex = shader_variant(shaders::tank_frame_vert),
      .fragment = shader_variant(shaders::tank_frame_frag),
      .color_formats = {k_color_format},
      .depth_format = k_depth_format,
      .depth_test = true,
      .depth_write = true,
      .depth_compare = VK_COMPARE_OP_LESS,
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer,
                    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                   {LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer,
                    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT}}};
}
constexpr uint32_t k_tank_frame_vertices = LIQUID_TANK_FRAME_BARS * LIQUID_TANK_FRAME_BAR_VERTICES;  // tank_frame.vert

}  // namespace

std::optional<int> composite_output_encoding(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
      return LIQUID_OUTPUT_DISPLAY;
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_SRGB:
      return LIQUID_OUTPUT_LINEAR;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
      return LIQUID_OUTPUT_HDR;
    default:
      return std::nullopt;
  }
}

bool is_composite_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

glm::mat4 raymarch_view_projection(const SimulationSetup& setup, const CameraView& camera, float aspect) {
  const float far_plane = 4.0f * glm::length(setup.domain) + glm::length(camera.position - camera.target) * 2.0f;
  return view_projection(camera, aspect, 0.01f, far_plane);
}

RaymarchPass::RaymarchPass(engine::vk::Context& context, const LiquidNode& node, ViewOutput output)
    : node_(node),
      bricks_(3, (node_setup(node).grid_cells + k_brick_cells - 1) / k_brick_cells, node_grid_layout(node).path),
      occupancy_(context, engine::vk::GraphicsPipelineDesc{
                              .name = "liquid.occupancy",
                              .vertex = grid_pass_shaders(bricks_).vertex,
                              .geometry = grid_pass_shaders(bricks_).geometry,
                              .fragment = shader_variant(shaders::occupancy_frag, bricks_.atlas() ? shader_feature::ATLAS : 0u),
                              .color_formats = {VK_FORMAT_R16_SFLOAT},
                              .bindings = {{LIQUID_BINDING_OCCUPANCY_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                              .push_constant_size = sizeof(gpu::OccupancyPush)}),
      coarse_(context, node, bricks_),
      // Compositing takes a pipeline per host format instead (composite_pipelines_).
      raymarch_(output == ViewOutput::HostTargets
                    ? engine::vk::GraphicsPipeline()
                    : engine::vk::GraphicsPipeline(context, raymarch_pipeline_desc(node, bricks_, false, false))),
      context_(context),
      linear_(context, VK_FILTER_LINEAR),
      nearest_(context, VK_FILTER_NEAREST),
      uniforms_(context, node, sizeof(gpu::RaymarchUniforms)),
      composite_(output == ViewOutput::HostTargets) {
  // Composited, the tiles without liquid show the host's frame: nothing to draw there.
  if (!composite_) {
    background_ = engine::vk::GraphicsPipeline(context, raymarch_pipeline_desc(node, bricks_, false, true));
    tank_frame_ = engine::vk::GraphicsPipeline(context, tank_frame_pipeline_desc());
  }
  if (!composite_) {
    meshes_ = std::make_unique<MeshDrawPass>(context, node, k_color_format, k_depth_format);
    if (meshes_->empty()) meshes_.reset();
  }
}

RaymarchPass::Outputs RaymarchPass::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                           const RenderSettings& settings, const RaymarchView& view_input,
                                           const HostTargets* targets) {
  if (bool(targets) != composite_)
    throw UsageError(composite_ ? "liquid.raymarch: a compositing pass draws into host targets"
                                      : "liquid.raymarch: host targets need a compositing pass");
  const SimulationSetup& setup = node_setup(node_);
  const engine::vk::UniformSlice solver = uniforms_.begin_frame();

  const glm::ivec3 bricks = bricks_.cells;
  const GridLayout& grid = node_grid_layout(node_);
  const glm::mat4& vp = view_input.view_projection;
  const VkRect2D viewport = view_input.viewport;
  if (viewport.extent.width == 0 || viewport.extent.height == 0 || viewport.offset.x < 0 || viewport.offset.y < 0 ||
      viewport.offset.x + viewport.extent.width > settings.width ||
      viewport.offset.y + viewport.extent.height > settings.height)
    throw ArgumentError("liquid: the view's viewport " + std::to_string(viewport.extent.width) + "x" +
                        std::to_string(viewport.extent.height) + " at (" + std::to_string(viewport.offset.x) +
                        ", " + std::to_string(viewport.offset.y) + ") is not inside the " +
                        std::to_string(settings.width) + "x" + std::to_string(settings.height) + " targets");
  if (view_input.reversed_z && !composite_)
    throw UsageError("liquid.raymarch: reversed Z is for a host's targets; the renderer's own frame is forward");
  // Compositing: the pipeline for the host's colour and depth formats and depth convention, made once.
  const engine::vk::GraphicsPipeline* pipeline = &raymarch_;
  if (composite_) {
    const CompositeKey key{graph.image_desc(targets->color).format, graph.image_desc(targets->depth).format,
                           view_input.reversed_z};
    auto& cached = composite_pipelines_[key];
    if (!cached)
      cached = std::make_unique<engine::vk::GraphicsPipeline>(
          context_, raymarch_pipeline_desc(node_, bricks_, true, false, key.reversed_z, key.color, key.depth));
    pipeline = cached.get();
  }
  gpu::RaymarchUniforms render{};
  render.inverse_view_projection = glm::inverse(vp);
  render.view_projection = vp;
  render.near_depth = view_input.reversed_z ? 1.0f : 0.0f;
  render.exposure = settings.exposure;
  render.viewport_x = float(viewport.offset.x);
  render.viewport_y = float(viewport.offset.y);
  render.iso_level = settings.iso_level;
  render.sun_direction = glm::normalize(glm::vec3(0.45f, 0.8f, 0.35f));
  render.fine_step_cells = k_fine_step_cells;
  render.bricks = bricks;
  render.brick_cells = float(k_brick_cells);
  render.brick_columns = bricks_.tiles.x;
  render.brick_rows = bricks_.tiles.y;
  const CoarseMarch::Sizes sizes = CoarseMarch::sizes(viewport.extent);
  render.viewport_width = float(viewport.extent.width);
  render.viewport_height = float(viewport.extent.height);
  render.coarse_width = int(sizes.rays.width);
  render.coarse_height = int(sizes.rays.height);
  render.tiles_x = int(sizes.tiles.width);
  render.tiles_y = int(sizes.tiles.height);
  const engine::vk::UniformSlice view = uniforms_.push(render);

  // Occupancy: one texel per brick, the brick's largest density.
  struct OccupancyData {
    engine::passes::PassBindings bindings;
    ImageHandle occupancy;
  };
  const ImageHandle density = images.density;
  const ImageHandle occupancy =
      graph
          .add_pass<OccupancyData>(
              "liquid.occupancy",
              [&](PassBuilder& b, OccupancyData& d) {
                d.bindings = engine::passes::PassBindings(occupancy_);
                d.bindings.bind_image(b, LIQUID_BINDING_OCCUPANCY_DENSITY, density, nearest_.handle());
                d.occupancy = b.write(b.create("liquid.occupancy", bricks_.image_desc(VK_FORMAT_R16_SFLOAT, 0)),
                                      Access::ColorAttachmentWrite);
              },
              [this, push = gpu::OccupancyPush{grid.cells, k_brick_cells, bricks_.cells, grid.tiles.x, grid.tiles.y,
                                               bricks_.tiles.x, bricks_.tiles.y}](PassContext& ctx,
                                                                                  const OccupancyData& d) {
                d.bindings.bind_and_push(ctx);
                occupancy_.push_constants(ctx.cmd, push);
                engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
              })
          .occupancy;

  const engine::vk::ImageDesc color_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_color_format, 0};
  const engine::vk::ImageDesc depth_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_depth_format, 0};
  // Mesh obstacles first: the raymarch keeps their pixels where they are nearer than what it finds.
  std::optional<MeshDrawPass::Targets> drawn;
  if (meshes_)
    drawn = meshes_->add_to(graph, {graph.create_image("liquid.color", color_desc), graph.create_image("liquid.depth", depth_desc)},
                            vp, viewport, render.sun_direction);
  const auto bind_march = [&](PassBuilder& b, const engine::vk::GraphicsPipeline& pipeline) {
    engine::passes::PassBindings bindings(pipeline);
    bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
    bindings.bind_uniform(LIQUID_BINDING_VIEW_UNIFORMS, view);
    bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_DENSITY, density, linear_.handle());
    bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_OCCUPANCY, occupancy, nearest_.handle());
    return bindings;
  };
  const CoarseMarch::Outputs coarse =
      coarse_.add_to(graph, bind_march, view, nearest_.handle(), vp, setup.domain, viewport);

  // The full-resolution raymarch, as tiles over the view: those with liquid with the whole shader,
  // the others (not when compositing: they show the host's frame) with the specialization without
  // the liquid.
  struct RaymarchData {
    engine::passes::PassBindings bindings;
    engine::passes::PassBindings background_bindings;
    engine::passes::PassBindings tank_frame_bindings;
    VkViewport tiles_viewport{};
    VkViewport viewport{};
    VkRect2D scissor{};
    uint32_t vertices = 0;
    Outputs out;
  };
  return graph.add_pass<RaymarchData>(
      "liquid.raymarch",
      [&](PassBuilder& b, RaymarchData& d) {
        const auto bind = [&](const engine::vk::GraphicsPipeline& pipeline) {
          engine::passes::PassBindings bindings = bind_march(b, pipeline);
          bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_COARSE, coarse.crossings, nearest_.handle());
          bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_TILES, coarse.tile_kinds, nearest_.handle());
          return bindings;
        };
        d.bindings = bind(*pipeline);
        if (!composite_) {
          d.background_bindings = bind(background_);
          d.tank_frame_bindings = engine::passes::PassBindings(tank_frame_);
          d.tank_frame_bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
          d.tank_frame_bindings.bind_uniform(LIQUID_BINDING_VIEW_UNIFORMS, view);
        }
        // The tiles whole (raymarch_tile.vert), cut to the view by the scissor.
        d.tiles_viewport = {float(viewport.offset.x), float(viewport.offset.y),
                            float(sizes.tiles.width * LIQUID_RAYMARCH_TILE_PIXELS),
                            float(sizes.tiles.height * LIQUID_RAYMARCH_TILE_PIXELS), 0.0f, 1.0f};
        d.viewport = {float(viewport.offset.x), float(viewport.offset.y), float(viewport.extent.width),
                      float(viewport.extent.height), 0.0f, 1.0f};
        d.scissor = viewport;
        d.vertices = sizes.tiles.width * sizes.tiles.height;  // a point each
        Outputs& out = d.out;
        if (targets) {  // over the host's colour, tested against and written into its depth
          out.color = b.write(targets->color, Access::ColorAttachmentBlend);
          out.depth = b.write(targets->depth, Access::DepthAttachmentWrite, {engine::graph::LoadOp::Load, {}});
        } else if (drawn) {  // over the meshes, tested against their depth
          out.color = b.write(drawn->color, Access::ColorAttachmentWrite, {engine::graph::LoadOp::Load, {}});
          out.depth = b.write(drawn->depth, Access::DepthAttachmentWrite, {engine::graph::LoadOp::Load, {}});
        } else {
          out.color = b.write(b.create("liquid.color", color_desc), Access::ColorAttachmentWrite);
          out.depth = b.write(b.create("liquid.depth", depth_desc), Access::DepthAttachmentWrite,
                              engine::graph::clear_depth(1.0f));
        }
      },
      [composite = composite_](PassContext& ctx, const RaymarchData& d) {
        const auto draw = [&](const engine::passes::PassBindings& bindings, const VkViewport& viewport,
                              uint32_t vertices) {
          bindings.bind_and_push(ctx);
          vkCmdSetViewport(ctx.cmd, 0, 1, &viewport);
          vkCmdSetScissor(ctx.cmd, 0, 1, &d.scissor);
          vkCmdDraw(ctx.cmd, vertices, 1, 0, 0);
        };
        draw(d.bindings, d.tiles_viewport, d.vertices);
        if (composite) return;
        draw(d.background_bindings, d.tiles_viewport, d.vertices);
        draw(d.tank_frame_bindings, d.viewport, k_tank_frame_vertices);
      }).out;
}

}  // namespace liquid
