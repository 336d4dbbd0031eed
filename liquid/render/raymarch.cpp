#include "liquid/render/raymarch.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/solver/images.h"
#include "liquid/solver/simulation.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"
#include "shaders/liquid/render/view_blocks.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace liquid {

namespace {

constexpr float k_fine_step_cells = 0.6f;

// The scene's constants plus the raymarch's own (constant_id LIQUID_RAYMARCH_COMPOSITE_ID).
std::vector<int32_t> raymarch_specialization(const LiquidNode& node, bool composite) {
  static_assert(LIQUID_RAYMARCH_COMPOSITE_ID == specialization_id::count, "the raymarch's constant follows the scene's");
  std::vector<int32_t> constants = scene_specialization(node.scene(), node.simulation().setup());
  constants.push_back(composite ? 1 : 0);
  return constants;
}

}  // namespace

glm::mat4 raymarch_view_projection(const SimulationSetup& setup, const CameraView& camera, float aspect) {
  const float far_plane = 4.0f * glm::length(setup.domain) + glm::length(camera.position - camera.target) * 2.0f;
  return view_projection(camera, aspect, 0.01f, far_plane);
}

RaymarchPass::RaymarchPass(engine::vk::Context& context, const LiquidNode& node, bool composite)
    : node_(node),
      bricks_(3, (node.simulation().setup().grid_cells + k_brick_cells - 1) / k_brick_cells, node.simulation().grid_layout().path),
      occupancy_(context, engine::vk::GraphicsPipelineDesc{
                              .name = "liquid.occupancy",
                              .vertex = grid_pass_shaders(bricks_).vertex,
                              .geometry = grid_pass_shaders(bricks_).geometry,
                              .fragment = bricks_.atlas() ? liquid_shaders::occupancy_frag_atlas
                                                          : liquid_shaders::occupancy_frag,
                              .color_formats = {VK_FORMAT_R16_SFLOAT},
                              .bindings = {{LIQUID_BINDING_OCCUPANCY_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                              .push_constant_size = sizeof(gpu::OccupancyPush)}),
      raymarch_(context, engine::vk::GraphicsPipelineDesc{
                             .name = "liquid.raymarch",
                             .vertex = engine::passes::fullscreen_vertex_shader(),
                             .fragment = bricks_.atlas() ? liquid_shaders::raymarch_frag_atlas : liquid_shaders::raymarch_frag,
                             .color_formats = {k_color_format},
                             // Composited: blended over the host's colour (the shader writes the
                             // liquid's coverage in alpha).
                             .blend = {composite ? engine::vk::BlendMode::Alpha : engine::vk::BlendMode::None},
                             .depth_format = k_depth_format,
                             .depth_test = true,
                             .depth_write = true,
                             .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {LIQUID_BINDING_RAYMARCH_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {LIQUID_BINDING_RAYMARCH_OCCUPANCY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                             .specialization = raymarch_specialization(node, composite)}),
      linear_(context, VK_FILTER_LINEAR),
      nearest_(context, VK_FILTER_NEAREST),
      uniforms_(context, node, sizeof(gpu::RaymarchUniforms)),
      composite_(composite) {}

RaymarchPass::Outputs RaymarchPass::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                           const RenderSettings& settings, const CameraView& camera,
                                           const HostTargets* targets) {
  if (bool(targets) != composite_)
    throw std::logic_error(composite_ ? "liquid.raymarch: a compositing pass draws into host targets"
                                      : "liquid.raymarch: host targets need a compositing pass");
  const SimulationSetup& setup = node_.simulation().setup();
  const engine::vk::UniformSlice solver = uniforms_.begin_frame();

  const glm::ivec3 bricks = bricks_.cells;
  const GridLayout& grid = node_.simulation().grid_layout();
  const glm::mat4 vp = raymarch_view_projection(setup, camera, float(settings.width) / float(settings.height));
  gpu::RaymarchUniforms render{};
  render.inverse_view_projection = glm::inverse(vp);
  render.view_projection = vp;
  render.camera_position = camera.position;
  render.iso_level = settings.iso_level;
  render.sun_direction = glm::normalize(glm::vec3(0.45f, 0.8f, 0.35f));
  render.fine_step_cells = k_fine_step_cells;
  render.bricks = bricks;
  render.brick_cells = float(k_brick_cells);
  render.brick_columns = bricks_.tiles.x;
  render.brick_rows = bricks_.tiles.y;
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
  struct RaymarchData {
    engine::passes::PassBindings bindings;
    Outputs out;
  };
  return graph.add_pass<RaymarchData>(
      "liquid.raymarch",
      [&](PassBuilder& b, RaymarchData& d) {
        d.bindings = engine::passes::PassBindings(raymarch_);
        d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
        d.bindings.bind_uniform(LIQUID_BINDING_VIEW_UNIFORMS, view);
        d.bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_DENSITY, density, linear_.handle());
        d.bindings.bind_image(b, LIQUID_BINDING_RAYMARCH_OCCUPANCY, occupancy, nearest_.handle());
        Outputs& out = d.out;
        if (targets) {  // over the host's colour, tested against and written into its depth
          out.color = b.write(targets->color, Access::ColorAttachmentBlend);
          out.depth = b.write(targets->depth, Access::DepthAttachmentWrite, {engine::graph::LoadOp::Load, {}});
        } else {
          out.color = b.write(b.create("liquid.color", color_desc), Access::ColorAttachmentWrite);
          out.depth = b.write(b.create("liquid.depth", depth_desc), Access::DepthAttachmentWrite,
                              engine::graph::clear_depth(1.0f));
        }
      },
      [](PassContext& ctx, const RaymarchData& d) {
        d.bindings.bind_and_push(ctx);
        engine::passes::draw_fullscreen(ctx.cmd);
      }).out;
}

}  // namespace liquid
