#include "liquid/render/raymarch.h"

#include "embedded_shaders.h"
#include "engine/passes/fullscreen.h"
#include "liquid/specialization.h"
#include "liquid/uniforms.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace liquid {

using engine::graph::Access;
using engine::graph::ImageHandle;
using engine::graph::PassBuilder;
using engine::graph::PassContext;
using engine::vk::DescriptorKind;

namespace {

// Mirror of RenderUniforms in shaders/render/raymarch.frag (std140).
struct RenderUniforms {
  glm::mat4 inverse_view_projection;
  glm::mat4 view_projection;
  glm::vec4 camera_position;
  glm::vec4 sun_direction;
  glm::vec4 params;
  glm::ivec4 bricks;
};
static_assert(sizeof(RenderUniforms) == 192);

constexpr float k_fine_step_cells = 0.6f;
constexpr float k_bisection_steps = 5.0f;

}  // namespace

RaymarchPass::RaymarchPass(engine::vk::Context& context, const LiquidNode& node)
    : node_(node),
      occupancy_(context, engine::vk::GraphicsPipelineDesc{
                              .name = "liquid.occupancy",
                              .vertex = engine::passes::fullscreen_layered_vertex_shader(),
                              .geometry = engine::passes::fullscreen_layered_geometry_shader(),
                              .fragment = shaders::occupancy_frag,
                              .color_formats = {VK_FORMAT_R16_SFLOAT},
                              .bindings = {{0, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                              .push_constant_size = 16}),
      raymarch_(context, engine::vk::GraphicsPipelineDesc{
                             .name = "liquid.raymarch",
                             .vertex = engine::passes::fullscreen_vertex_shader(),
                             .fragment = shaders::raymarch_frag,
                             .color_formats = {k_color_format},
                             .depth_format = k_depth_format,
                             .depth_test = true,
                             .depth_write = true,
                             .bindings = {{0, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {1, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {2, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                          {3, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                             .specialization = scene_specialization(node.setup())}),
      linear_(context, VK_FILTER_LINEAR),
      nearest_(context, VK_FILTER_NEAREST),
      uniforms_(context, 4096, 3) {}

RaymarchPass::Outputs RaymarchPass::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                           const RenderSettings& settings, const CameraView& camera) {
  const SimulationSetup& setup = node_.setup();
  uniforms_.begin_frame();
  StepInputs inputs;
  inputs.obstacle_poses = node_.obstacle_poses(node_.time());
  const engine::vk::UniformSlice solver = uniforms_.push(make_uniforms(setup, inputs));

  const glm::ivec3 bricks = (setup.grid_cells + k_brick_cells - 1) / k_brick_cells;
  const float aspect = float(settings.width) / float(settings.height);
  const float far_plane = 4.0f * glm::length(setup.domain) + glm::length(camera.position - camera.target) * 2.0f;
  const glm::mat4 vp = view_projection(camera, aspect, 0.01f, far_plane);
  const RenderUniforms render{glm::inverse(vp), vp, glm::vec4(camera.position, 1.0f),
                              glm::vec4(glm::normalize(glm::vec3(0.45f, 0.8f, 0.35f)), 0.0f),
                              glm::vec4(settings.iso_level, k_fine_step_cells, float(k_brick_cells), k_bisection_steps),
                              glm::ivec4(bricks, 0)};
  const engine::vk::UniformSlice view = uniforms_.push(render);

  // Occupancy: one texel per brick, the brick's largest density.
  struct OccupancyData {
    ImageHandle occupancy;
  };
  const ImageHandle density = images.density;
  const ImageHandle occupancy =
      graph
          .add_pass<OccupancyData>(
              "liquid.occupancy",
              [&](PassBuilder& b, OccupancyData& d) {
                b.read(density, Access::FragmentSampled);
                d.occupancy = b.write(
                    b.create("liquid.occupancy", {engine::vk::ImageKind::Image3D, uint32_t(bricks.x), uint32_t(bricks.y),
                                                  uint32_t(bricks.z), VK_FORMAT_R16_SFLOAT, 0}),
                    Access::ColorAttachmentWrite);
              },
              [this, density](PassContext& ctx, const OccupancyData&) {
                occupancy_.bind(ctx.cmd, ctx.width, ctx.height);
                occupancy_.push_image(ctx.cmd, 0, ctx.image(density).sampled_view(), nearest_.handle());
                const glm::ivec4 push(k_brick_cells, 0, 0, 0);
                occupancy_.push_constants(ctx.cmd, push);
                engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
              })
          .occupancy;

  const engine::vk::ImageDesc color_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_color_format, 0};
  const engine::vk::ImageDesc depth_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_depth_format, 0};
  return graph.add_pass<Outputs>(
      "liquid.raymarch",
      [&](PassBuilder& b, Outputs& out) {
        b.read(density, Access::FragmentSampled);
        b.read(occupancy, Access::FragmentSampled);
        out.color = b.write(b.create("liquid.color", color_desc), Access::ColorAttachmentWrite);
        out.depth = b.write(b.create("liquid.depth", depth_desc), Access::DepthAttachmentWrite,
                            engine::graph::clear_depth(1.0f));
      },
      [this, solver, view, density, occupancy](PassContext& ctx, const Outputs&) {
        raymarch_.bind(ctx.cmd, ctx.width, ctx.height);
        raymarch_.push_uniform(ctx.cmd, 0, solver.buffer, solver.offset, solver.size);
        raymarch_.push_uniform(ctx.cmd, 1, view.buffer, view.offset, view.size);
        raymarch_.push_image(ctx.cmd, 2, ctx.image(density).sampled_view(), linear_.handle());
        raymarch_.push_image(ctx.cmd, 3, ctx.image(occupancy).sampled_view(), nearest_.handle());
        engine::passes::draw_fullscreen(ctx.cmd);
      });
}

}  // namespace liquid
