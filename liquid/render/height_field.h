// The shallow-water view (section 6, figure 4): the 2D simulation plane laid on the ground
// (scene x -> world x, scene y -> world z, up = world y), drawn as a lit sandy ground b(x, y) and a
// semi-transparent water surface at b + h, h = rest_depth * rho / rho0.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/buffer.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/physics/setup.h"
#include "liquid/render/view_uniforms.h"
#include "liquid/renderer.h"

namespace liquid {

// A camera looking at the centre of the plane from above and in front (+z), about 50 degrees
// above the horizon, framing the whole domain; the scene's own camera when it has one.
CameraView default_height_field_camera(const Scene& scene, const SimulationSetup& setup);

// Draws a shallow-water node's ground and water as two meshes of one vertex per grid cell, made in
// the vertex shader from gl_VertexIndex, with depth testing. An index buffer shares each vertex
// between its six triangles, so the vertex work (five surface lookups each) is done once per vertex.
class HeightFieldPass {
 public:
  // Throws UsageError when the node is not a 2D shallow-water simulation.
  HeightFieldPass(engine::vk::Context& context, const LiquidNode& node);

  // Returns a new RGBA8_UNORM image of settings.width x settings.height.
  engine::graph::ImageHandle add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                    const RenderSettings& settings, const CameraView& camera);

  // Water thinner than this fraction of the rest depth is not drawn (dry ground).
  static constexpr float k_dry_fraction = 0.05f;

 private:
  const LiquidNode& node_;
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler linear_;
  ViewUniforms uniforms_;
  engine::vk::Buffer indices_;  // 6 per quad of the (cells + 2)^2 vertex grid, far rows first
  uint32_t index_count_ = 0;
};

}  // namespace liquid
