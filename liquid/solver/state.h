// The solver's persistent GPU state: particle positions and velocities (RGBA32F, ping-ponged; a
// W x H texture holds up to W * H particles, texels past the active count are inactive) and the
// grids of the last step (splat, updated velocity, density). The graph imports these every frame.
#pragma once

#include "engine/vk/image.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/grid_layout.h"

#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace engine::vk {
class Context;
}

namespace liquid {

constexpr VkFormat k_particle_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // positions and velocities
constexpr VkFormat k_grid_velocity_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat k_density_format = VK_FORMAT_R16_SFLOAT;  // rho / rho0, for rendering
// The pressure projection's density correction per cell, -grad psi (m; projection.glsl).
constexpr VkFormat k_density_correction_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat k_body_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // body state, the liquid's force and torque

// The splat's format for a scene's `requested` one and what the device can blend into. Auto takes
// RGBA32F where it is blendable and falls back to RGBA16F (`fell_back`) where it is not. Throws
// DeviceError naming the format when the device cannot blend into the one needed.
struct SplatFormatChoice {
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  bool fell_back = false;  // auto, and RGBA32F is not blendable here
};
SplatFormatChoice choose_splat_format(SplatFormat requested, bool rgba32f_blendable, bool rgba16f_blendable);

struct LiquidState {
  // The grids are stored as `layout` says (3D images or atlases in 3D); `body_texels` is the
  // body-state texture's first contents (liquid/solver/bodies.h).
  // `affine_textures` C_p textures per particle texture (SolverVariant::affine_textures()).
  LiquidState(engine::vk::Context& context, const SimulationSetup& setup, const GridLayout& layout,
              VkFormat splat_format, const std::vector<glm::vec4>& body_texels, int affine_textures);

  std::array<engine::vk::Image, 2> positions;   // xyz (m), w = 1 active
  std::array<engine::vk::Image, 2> velocities;  // xyz (m/s)
  std::array<std::vector<engine::vk::Image>, 2> affine;  // the affine transfer's C_p (1/s), zero at first
  engine::vk::Image splat;                      // (sum w u, sum w)
  engine::vk::Image grid_velocity;              // (u', fluid flag)
  engine::vk::Image density;                    // rho / rho0
  // LIQUID_BODY_TEXELS x obstacles (at least 1 row): the dynamic obstacles' state (shaders/liquid/
  // shared.h), ping-ponged by the integration pass.
  std::array<engine::vk::Image, 2> bodies;
  int current = 0;                              // which of the particle pair holds the latest particles
  int body_current = 0;                         // which of the body pair holds the latest state
};

}  // namespace liquid
