// The secondary particles (Scene::whitewater) over the 3D view: point sprites alpha-blended into
// the view's colour, depth-tested against its depth without writing it, so the liquid's surface,
// obstacles and a host's geometry in front hide them. Spray and foam are white; bubbles are drawn
// a little toward the camera, so those just under the surface show through it, bluish and faint.
// Shaders: shaders/liquid/render/whitewater_draw.vert, .frag.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/node.h"

#include <glm/glm.hpp>

#include <compare>
#include <map>
#include <memory>

namespace liquid {

class WhitewaterDraw {
 public:
  WhitewaterDraw(engine::vk::Context& context, const LiquidNode& node);

  struct Targets {
    engine::graph::ImageHandle color, depth;
  };
  // Draws the secondary particles in `images` (whitewater_positions) into `targets` (any colour
  // format the composite takes, its depth convention `reversed_z`) seen through `view_projection`
  // in `viewport`; returns the targets' new versions. `exposure` scales an HDR target's radiance.
  Targets add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, Targets targets,
                 const glm::mat4& view_projection, bool reversed_z, VkRect2D viewport, float exposure);

 private:
  struct Key {
    VkFormat color;
    VkFormat depth;
    bool reversed_z;
    auto operator<=>(const Key&) const = default;
  };
  const engine::vk::GraphicsPipeline& pipeline(const Key& key);

  engine::vk::Context& context_;
  const LiquidNode& node_;
  std::map<Key, std::unique_ptr<engine::vk::GraphicsPipeline>> pipelines_;  // made on first use
  engine::vk::Sampler nearest_;
};

}  // namespace liquid
