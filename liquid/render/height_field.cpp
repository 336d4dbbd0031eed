#include "liquid/render/height_field.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/images.h"
#include "liquid/solver/node_view.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shader_families.h"
#include "shaders/liquid/render/view_blocks.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace liquid {

namespace {

constexpr float k_camera_elevation_degrees = 50.0f;
constexpr float k_camera_fov_degrees = 40.0f;
// Heights are drawn at their true scale.
constexpr float k_vertical_scale = 1.0f;
// Towards the sun: high, beyond the plane's far side and to the right, so the waves facing the
// default camera catch its highlight.
const glm::vec3 k_sun_direction = glm::normalize(glm::vec3(0.35f, 0.7f, -0.6f));
// The sky where no mesh covers the frame (the colour the water reflects near the horizon).
constexpr glm::vec4 k_sky{0.70f, 0.79f, 0.89f, 1.0f};


const LiquidNode& require_shallow_water(const LiquidNode& node) {
  if (node.dimension() != 2 || !node_setup(node).shallow_water)
    throw UsageError("liquid: the height-field view needs a 2D shallow-water scene");
  return node;
}

}  // namespace

CameraView default_height_field_camera(const Scene& scene, const SimulationSetup& setup) {
  if (scene.camera) {
    const Camera& c = *scene.camera;
    return {c.position, c.target, {0.0f, 1.0f, 0.0f}, c.fov_y_degrees};
  }
  const glm::vec2 plane(setup.domain.x, setup.domain.y);
  const glm::vec3 target(0.5f * plane.x, 0.5f * setup.rest_depth, 0.5f * plane.y);
  // Far enough that the plane, foreshortened by the elevation, fills most of a 4:3 frame.
  const float extent = std::max(plane.x, plane.y);
  const float distance = 1.55f * extent;
  const float elevation = glm::radians(k_camera_elevation_degrees);
  const glm::vec3 direction(0.0f, std::sin(elevation), std::cos(elevation));  // from the front, +z
  return {target + distance * direction, target, {0.0f, 1.0f, 0.0f}, k_camera_fov_degrees};
}

HeightFieldPass::HeightFieldPass(engine::vk::Context& context, const LiquidNode& node)
    : node_(require_shallow_water(node)),
      pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.height_field",
                    .vertex = shader_variant(shaders::height_field_vert),
                    .fragment = shader_variant(shaders::height_field_frag),
                    .color_formats = {k_color_format},
                    // The ground writes alpha 1, so one blended pipeline draws both layers.
                    .blend = {engine::vk::BlendMode::Alpha},
                    .depth_format = k_depth_format,
                    .depth_test = true,
                    .depth_write = true,
                    .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, VK_SHADER_STAGE_VERTEX_BIT},
                                 {LIQUID_BINDING_VIEW_UNIFORMS, DescriptorKind::UniformBuffer,
                                  VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_HEIGHT_FIELD_DENSITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
                    .push_constant_size = sizeof(gpu::HeightFieldPush),
                    .specialization = scene_specialization(node.scene(), node_setup(node))}),
      linear_(context, VK_FILTER_LINEAR),
      uniforms_(context, node, sizeof(gpu::HeightFieldUniforms)) {
  // Vertex g = (x, y) of the (cells + 2)^2 grid (cells plus the edge ring) has index y (n.x + 2) + x.
  const glm::ivec2 n(node_setup(node).grid_cells.x, node_setup(node).grid_cells.y);
  const uint32_t row = uint32_t(n.x + 2);
  static constexpr glm::uvec2 k_corners[6] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<uint32_t> indices;
  indices.reserve(6u * uint32_t(n.x + 1) * uint32_t(n.y + 1));
  for (uint32_t y = 0; y <= uint32_t(n.y); ++y)
    for (uint32_t x = 0; x <= uint32_t(n.x); ++x)
      for (const glm::uvec2& c : k_corners) indices.push_back((y + c.y) * row + x + c.x);
  index_count_ = uint32_t(indices.size());
  indices_ = engine::vk::Buffer(context, indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                engine::vk::MemoryUsage::HostVisible, "liquid.height_field.indices");
  std::memcpy(indices_.mapped(), indices.data(), indices.size() * sizeof(uint32_t));
  indices_.flush();
}

ImageHandle HeightFieldPass::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                    const RenderSettings& settings, const CameraView& camera) {
  const SimulationSetup& setup = node_setup(node_);
  const engine::vk::UniformSlice solver = uniforms_.begin_frame();

  const float rest_depth = setup.rest_depth;
  const float extent = std::max(setup.domain.x, setup.domain.y);
  const float aspect = float(settings.width) / float(settings.height);
  const float far_plane = 4.0f * extent + 2.0f * glm::length(camera.position - camera.target);
  const float near_plane = 1e-3f * far_plane;
  // The sides drop below the bed by a slab as thick as the rest depth (at least 2% of the plane).
  const float base = -std::max(rest_depth, 0.02f * extent);
  gpu::HeightFieldUniforms view{};
  view.view_projection = view_projection(camera, aspect, near_plane, far_plane);
  view.camera_position = camera.position;
  view.rest_depth = rest_depth;
  view.sun_direction = k_sun_direction;
  view.dry_threshold = k_dry_fraction * rest_depth;
  view.vertical_scale = k_vertical_scale;
  view.skirt_base = base;
  const engine::vk::UniformSlice view_slice = uniforms_.push(view);

  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle color;
    ImageHandle depth;
  };
  const ImageHandle density = images.density;
  const engine::vk::ImageDesc color_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_color_format, 0};
  const engine::vk::ImageDesc depth_desc{engine::vk::ImageKind::Image2D, settings.width, settings.height, 1,
                                         k_depth_format, 0};
  return graph
      .add_pass<Data>(
          "liquid.height_field",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, solver);
            d.bindings.bind_uniform(LIQUID_BINDING_VIEW_UNIFORMS, view_slice);
            d.bindings.bind_image(b, LIQUID_BINDING_HEIGHT_FIELD_DENSITY, density, linear_.handle());
            // Blended: the water reads what the ground wrote.
            d.color = b.write(b.create("liquid.height_field", color_desc), Access::ColorAttachmentBlend,
                              engine::graph::clear_to(k_sky.r, k_sky.g, k_sky.b, k_sky.a));
            d.depth = b.write(b.create("liquid.height_field.depth", depth_desc), Access::DepthAttachmentWrite,
                              engine::graph::clear_depth(1.0f));
          },
          [this](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            // Ground first (opaque), then the water over it; rows run from far (scene y = 0) to
            // near for the default camera, so the blended water is drawn back to front.
            vkCmdBindIndexBuffer(ctx.cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
            pipeline_.push_constants(ctx.cmd, gpu::HeightFieldPush{LIQUID_HEIGHT_FIELD_GROUND});
            vkCmdDrawIndexed(ctx.cmd, index_count_, 1, 0, 0, 0);
            pipeline_.push_constants(ctx.cmd, gpu::HeightFieldPush{LIQUID_HEIGHT_FIELD_WATER});
            vkCmdDrawIndexed(ctx.cmd, index_count_, 1, 0, 0, 0);
          })
      .color;
}

}  // namespace liquid
