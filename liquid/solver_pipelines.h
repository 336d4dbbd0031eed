// The three raster pipelines of the solver for one dimension (2 or 3) and splat format, plus the
// nearest sampler all their texelFetch reads use.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/setup.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace liquid {

constexpr VkFormat k_particle_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // positions and velocities
constexpr VkFormat k_grid_velocity_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat k_density_format = VK_FORMAT_R16_SFLOAT;  // rho / rho0, for rendering

// The scene features the solver's shaders are specialized for (constant_id i = entry i, see
// shaders/liquid/common.glsl): obstacle count and shapes, shallow water, an integer gamma, emitters.
// They are fixed for a node's lifetime; obstacle poses, brushes and counts of particles are not.
std::vector<int32_t> solver_specialization(const SimulationSetup& setup);

struct SolverPipelines {
  SolverPipelines(engine::vk::Context& context, const SimulationSetup& setup, VkFormat splat_format);

  engine::vk::GraphicsPipeline splat;     // points -> additive blend into the splat grid
  engine::vk::GraphicsPipeline grid;      // full screen (layered in 3D) -> velocity + density
  engine::vk::GraphicsPipeline particle;  // full screen over the particle texture -> position + velocity
  engine::vk::Sampler nearest;
  int dimension;
  VkFormat splat_format;
};

}  // namespace liquid
