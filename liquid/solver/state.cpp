#include "liquid/solver/state.h"

#include "engine/graph/transfer.h"
#include "liquid/solver/bodies.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace liquid {

using engine::vk::Image;
using engine::vk::ImageDesc;
using engine::vk::ImageKind;

namespace {

constexpr VkImageUsageFlags k_usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

// Initial particles padded to the whole texture (inactive texels zero).
std::vector<glm::vec4> padded(const std::vector<glm::vec4>& values, const SimulationSetup& setup) {
  std::vector<glm::vec4> texels(size_t(setup.particle_texture.x) * setup.particle_texture.y, glm::vec4(0.0f));
  std::copy(values.begin(), values.end(), texels.begin());
  return texels;
}

}  // namespace

SplatFormatChoice choose_splat_format(SplatFormat requested, bool rgba32f_blendable, bool rgba16f_blendable) {
  const auto refuse = [](const char* name) {
    return DeviceError(std::string("the device cannot blend into ") + name + " render targets (splat_format)");
  };
  if (requested == SplatFormat::Rgba16f || (requested == SplatFormat::Auto && !rgba32f_blendable)) {
    if (!rgba16f_blendable) throw refuse(requested == SplatFormat::Auto ? "RGBA32F or RGBA16F" : "RGBA16F");
    return {VK_FORMAT_R16G16B16A16_SFLOAT, requested == SplatFormat::Auto};
  }
  if (!rgba32f_blendable) throw refuse("RGBA32F");
  return {VK_FORMAT_R32G32B32A32_SFLOAT, false};
}

LiquidState::LiquidState(engine::vk::Context& context, const SimulationSetup& setup, const GridLayout& layout,
                         VkFormat splat_format, const std::vector<glm::vec4>& body_texels, int affine_textures) {
  const ImageDesc particles{ImageKind::Image2D, uint32_t(setup.particle_texture.x), uint32_t(setup.particle_texture.y), 1,
                            k_particle_format, k_usage};
  for (int i = 0; i < 2; ++i) {
    positions[i] = Image(context, particles, "liquid.positions" + std::to_string(i));
    velocities[i] = Image(context, particles, "liquid.velocities" + std::to_string(i));
    for (int a = 0; a < affine_textures; ++a)
      affine[i].emplace_back(context, particles, "liquid.affine" + std::to_string(a) + "_" + std::to_string(i));
  }
  splat = Image(context, layout.image_desc(splat_format, k_usage), "liquid.splat");
  grid_velocity = Image(context, layout.image_desc(k_grid_velocity_format, k_usage), "liquid.grid_velocity");
  density = Image(context, layout.image_desc(k_density_format, k_usage), "liquid.density");

  const ImageDesc body_desc{ImageKind::Image2D, uint32_t(gpu_body_texels()), uint32_t(body_texels.size() / gpu_body_texels()),
                            1, k_body_format, k_usage};
  for (int i = 0; i < 2; ++i) {
    bodies[i] = Image(context, body_desc, "liquid.bodies" + std::to_string(i));
    engine::graph::upload_image(context, bodies[i], std::as_bytes(std::span(body_texels)));
  }

  const auto p = padded(setup.positions, setup);
  const auto v = padded(setup.velocities, setup);
  engine::graph::upload_image(context, positions[0], std::as_bytes(std::span(p)));
  engine::graph::upload_image(context, velocities[0], std::as_bytes(std::span(v)));
  const std::vector<glm::vec4> zero_affine(p.size(), glm::vec4(0.0f));
  for (auto& pair : affine)
    for (engine::vk::Image& image : pair) engine::graph::upload_image(context, image, std::as_bytes(std::span(zero_affine)));
  // Grids start empty (not undefined) so a host may render or read them before the first step.
  for (Image* grid : {&splat, &grid_velocity, &density}) {
    const ImageDesc& d = grid->desc();
    const std::vector<std::byte> zeros(size_t(d.width) * d.height * d.depth_or_layers *
                                       engine::vk::format_texel_size(d.format));
    engine::graph::upload_image(context, *grid, zeros);
  }
}

}  // namespace liquid
