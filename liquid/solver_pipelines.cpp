#include "liquid/solver_pipelines.h"

#include "embedded_shaders.h"
#include "engine/passes/fullscreen.h"
#include "liquid/specialization.h"

namespace liquid {

using engine::vk::BlendMode;
using engine::vk::DescriptorKind;
using engine::vk::GraphicsPipeline;
using engine::vk::GraphicsPipelineDesc;

namespace {

constexpr VkShaderStageFlags k_all = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

GraphicsPipeline make_splat(engine::vk::Context& context, int dimension, VkFormat format,
                            const std::vector<int32_t>& specialization) {
  return GraphicsPipeline(context, GraphicsPipelineDesc{
      .name = "liquid.splat",
      .vertex = dimension == 3 ? shaders::liquid_splat_vert_3d : shaders::liquid_splat_vert_2d,
      .fragment = shaders::liquid_splat_frag,
      .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
      .color_formats = {format},
      .blend = {BlendMode::Additive},
      .bindings = {{0, DescriptorKind::UniformBuffer, k_all},
                   {1, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                   {2, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .specialization = specialization});
}

GraphicsPipeline make_grid(engine::vk::Context& context, int dimension, const std::vector<int32_t>& specialization) {
  const bool layered = dimension == 3;
  return GraphicsPipeline(context, GraphicsPipelineDesc{
      .name = "liquid.grid",
      .vertex = layered ? engine::passes::fullscreen_layered_vertex_shader() : engine::passes::fullscreen_vertex_shader(),
      .geometry = layered ? engine::passes::fullscreen_layered_geometry_shader() : std::span<const uint32_t>{},
      .fragment = layered ? shaders::liquid_grid_frag_3d : shaders::liquid_grid_frag_2d,
      .color_formats = {k_grid_velocity_format, k_density_format},
      .bindings = {{0, DescriptorKind::UniformBuffer, k_all}, {1, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
      .specialization = specialization});
}

GraphicsPipeline make_particle(engine::vk::Context& context, int dimension,
                               const std::vector<int32_t>& specialization) {
  return GraphicsPipeline(context, GraphicsPipelineDesc{
      .name = "liquid.particle",
      .vertex = engine::passes::fullscreen_vertex_shader(),
      .fragment = dimension == 3 ? shaders::liquid_particle_frag_3d : shaders::liquid_particle_frag_2d,
      .color_formats = {k_particle_format, k_particle_format},
      .bindings = {{0, DescriptorKind::UniformBuffer, k_all},
                   {1, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {2, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {3, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                   {4, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
      .specialization = specialization});
}

}  // namespace

SolverPipelines::SolverPipelines(engine::vk::Context& context, const SimulationSetup& setup, VkFormat splat_format_)
    : splat(make_splat(context, setup.dimension, splat_format_, scene_specialization(setup))),
      grid(make_grid(context, setup.dimension, scene_specialization(setup))),
      particle(make_particle(context, setup.dimension, scene_specialization(setup))),
      nearest(context, VK_FILTER_NEAREST),
      dimension(setup.dimension),
      splat_format(splat_format_) {}

}  // namespace liquid
