// The 2D view (section 7's 2D examples): the density field drawn as liquid in the fitted domain,
// with obstacles, the tank's walls and, optionally, the particles as points on top.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/node.h"
#include "liquid/render/view_uniforms.h"
#include "shaders/liquid/render/view_blocks.h"
#include "liquid/renderer.h"

#include <glm/glm.hpp>

namespace liquid {

// Where the domain lands in a frame: fitted with its aspect ratio kept (letterboxed), leaving room
// for the tank's walls. Pixels are framebuffer pixels (y down); `origin` is the domain's (0, 0).
struct View2dLayout {
  glm::vec2 origin{0.0f};        // pixel of the domain's bottom-left corner
  float pixels_per_metre = 0.0f;
  float wall_pixels = 0.0f;      // tank wall thickness

  // Framebuffer pixel (y down) of a point of the domain (m, y up).
  glm::vec2 to_pixel(glm::vec2 p) const { return {origin.x + p.x * pixels_per_metre, origin.y - p.y * pixels_per_metre}; }
};

// Fits `domain` (m) into a width x height frame.
View2dLayout fit_view2d(glm::vec2 domain, uint32_t width, uint32_t height);

// Draws a 2D LiquidNode's density grid as liquid (and its particles when asked, its secondary
// particles when the scene has whitewater and RenderSettings::whitewater) into a new image.
class View2dPass {
 public:
  // Throws UsageError when the node is not two-dimensional. HostTargets: draw the
  // liquid alone with alpha into a host's rectangle (HostPanel) instead of a frame of its own.
  View2dPass(engine::vk::Context& context, const LiquidNode& node, ViewOutput output = ViewOutput::OwnFrame);

  // Returns a new RGBA8_UNORM image of settings.width x settings.height; with `panel`, the host
  // target's new version, drawn into its rectangle.
  engine::graph::ImageHandle add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                    const RenderSettings& settings, const HostPanel* panel = nullptr);

 private:
  // `count` points of `pipeline` (particles2d.vert's or whitewater2d.vert's) from the texture
  // `positions`, blended into `color`; returns its new version.
  engine::graph::ImageHandle draw_points(engine::graph::RenderGraph& graph, const engine::vk::GraphicsPipeline& pipeline,
                                         engine::graph::ImageHandle positions, engine::graph::ImageHandle color,
                                         const gpu::Particles2dPush& push, uint32_t count) const;

  const LiquidNode& node_;
  engine::vk::GraphicsPipeline depth_;   // the depth below the surface, per cell of the grid
  engine::vk::GraphicsPipeline liquid_;
  engine::vk::GraphicsPipeline opaque_panel_;  // panels only: HostPanel::background, PANEL off, into the rectangle
  engine::vk::GraphicsPipeline particles_;
  engine::vk::GraphicsPipeline whitewater_;  // scenes with whitewater
  engine::vk::Sampler linear_;
  engine::vk::Sampler nearest_;
  ViewUniforms uniforms_;
};

}  // namespace liquid
