// The raymarch's first two passes: a coarse march (one ray per LIQUID_RAYMARCH_COARSE_PIXELS^2
// pixels, shaders/liquid/render/raymarch_coarse.frag) that finds where each ray first crosses the
// liquid's surface, and the screen tiles' kinds (raymarch_tiles.frag): whether any coarse ray around
// a tile met the liquid. The full-resolution raymarch (raymarch.h) draws the tiles of each kind with
// its own pipeline and starts each pixel's march just before its coarse neighbours' crossings.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/passes/bindings.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/node.h"
#include "liquid/solver/grid_layout.h"

#include <glm/glm.hpp>

#include <functional>

namespace liquid {

class CoarseMarch {
 public:
  CoarseMarch(engine::vk::Context& context, const LiquidNode& node, const GridLayout& bricks);

  // The coarse rays' image and the tiles across a view of `view` pixels.
  struct Sizes {
    VkExtent2D rays;
    VkExtent2D tiles;
  };
  static Sizes sizes(VkExtent2D view);

  struct Outputs {
    engine::graph::ImageHandle crossings;   // per coarse ray: the distance to the surface, m, or LIQUID_RAYMARCH_NO_CROSSING
    engine::graph::ImageHandle tile_kinds;  // per tile: LIQUID_RAYMARCH_TILE_MISS or _LIQUID
  };
  // `bind_march` binds what the march reads (the solver's and the view's blocks, the density and the
  // occupancy) for a pipeline; `view_uniforms` is the view's block (RaymarchUniforms, its sizes from
  // sizes()). Only the rays that can reach the domain box are marched.
  using BindMarch = std::function<engine::passes::PassBindings(engine::graph::PassBuilder&,
                                                               const engine::vk::GraphicsPipeline&)>;
  Outputs add_to(engine::graph::RenderGraph& graph, const BindMarch& bind_march,
                 const engine::vk::UniformSlice& view_uniforms, VkSampler nearest, const glm::mat4& view_projection,
                 glm::vec3 domain, VkRect2D viewport) const;

 private:
  engine::vk::GraphicsPipeline coarse_;
  engine::vk::GraphicsPipeline tiles_;
};

}  // namespace liquid
