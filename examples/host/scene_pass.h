// The host's own pass, recorded with plain Vulkan outside the liquid's render graph: it clears its
// HDR colour target and its reversed-Z depth (to 0, the far plane) and draws a floor and a box in
// linear radiance. It takes each target from the layout and last access the graph left it in
// (engine::vk::Image::sync_state()) and records where it leaves them, so the graph's first pass on
// them next waits for exactly this pass.
#pragma once

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

#include <glm/glm.hpp>

class ScenePass {
 public:
  static constexpr VkFormat k_color_format = VK_FORMAT_R16G16B16A16_SFLOAT;  // linear HDR
  static constexpr VkFormat k_depth_format = VK_FORMAT_D32_SFLOAT;           // reversed Z

  explicit ScenePass(engine::vk::Context& context);

  // `floor_model` places the floor's square [-1, 1]^2 at y = 0, `box_model` the cube [-1, 1]^3.
  void record(VkCommandBuffer cmd, engine::vk::Image& color, engine::vk::Image& depth, const glm::mat4& view_projection,
              const glm::mat4& floor_model, const glm::mat4& box_model) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
};
