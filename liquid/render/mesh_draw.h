// The 3D view's mesh obstacles, rasterized into the frame's colour and depth before the raymarch,
// which is depth-tested against them (raymarch.frag traces only the analytic shapes). A mesh seen
// through the liquid is not refracted: the raymarch's refracted ray sees the analytic background.
// When compositing into a host's frame the host draws its own meshes. Shaders:
// shaders/liquid/render/mesh_draw.vert, mesh_draw.frag.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/node.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

class MeshDrawPass {
 public:
  MeshDrawPass(engine::vk::Context& context, const LiquidNode& node, VkFormat color_format, VkFormat depth_format);
  bool empty() const { return meshes_.empty(); }

  // Clears `color` and `depth` and draws the meshes where the node's obstacles are now, seen through
  // `view_projection` in `viewport`; returns their new versions.
  struct Targets {
    engine::graph::ImageHandle color, depth;
  };
  Targets add_to(engine::graph::RenderGraph& graph, Targets targets, const glm::mat4& view_projection,
                 VkRect2D viewport, glm::vec3 sun_direction);

 private:
  struct Mesh {
    size_t obstacle = 0;
    engine::vk::Image triangles;
    uint32_t triangle_count = 0;
  };
  const LiquidNode& node_;
  std::vector<Mesh> meshes_;
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
};

}  // namespace liquid
