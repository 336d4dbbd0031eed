// The three raster pipelines of the solver for one dimension (2 or 3) and splat format, plus the
// nearest sampler all their texelFetch reads use.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/setup.h"

#include <vulkan/vulkan.h>

namespace liquid {

constexpr VkFormat k_particle_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // positions and velocities
constexpr VkFormat k_grid_velocity_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat k_density_format = VK_FORMAT_R16_SFLOAT;  // rho / rho0, for rendering

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
