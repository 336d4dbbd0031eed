// The host's own pass, recorded with plain Vulkan outside the liquid's render graph: it clears its
// colour and depth targets and draws a floor and a box. It takes each target from the layout and
// last access the graph left it in (engine::vk::Image::sync_state()) and records where it leaves
// them, so the graph's first pass on them next waits for exactly this pass.
#pragma once

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

#include <glm/glm.hpp>

class ScenePass {
 public:
  explicit ScenePass(engine::vk::Context& context);

  void record(VkCommandBuffer cmd, engine::vk::Image& color, engine::vk::Image& depth, const glm::mat4& view_projection,
              glm::vec3 box_center, glm::vec3 box_half_extent, glm::vec2 floor_extent) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
};
