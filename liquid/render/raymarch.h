// The 3D view (section 7, figure 3): an occupancy pass (per-brick maximum density, for empty-space
// skipping), a coarse march (one ray per 2x2 pixels), a pass that sorts the screen's tiles by
// whether the coarse rays around them met the liquid, and the full-resolution raymarch of the
// density volume that writes colour and depth: tiles with liquid march from just before the coarse
// crossings, the others draw without the liquid's code.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/camera.h"
#include "liquid/render/coarse_march.h"
#include "liquid/node.h"
#include "liquid/physics/setup.h"
#include "liquid/render/mesh_draw.h"
#include "liquid/render/view_uniforms.h"
#include "liquid/renderer.h"
#include "liquid/solver/grid_layout.h"

#include <compare>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace liquid {

// How the raymarch writes a host's colour target of this format when compositing
// (LIQUID_OUTPUT_DISPLAY, _LINEAR or _HDR of shaders/liquid/render/view_blocks.h); empty for a
// format it cannot composite into.
std::optional<int> composite_output_encoding(VkFormat format);
// The host depth formats the composite tests against and writes; a stencil is left as it was.
bool is_composite_depth_format(VkFormat format);

// The view-projection the raymarch uses (near plane 1 cm, far plane beyond the domain and camera).
glm::mat4 raymarch_view_projection(const SimulationSetup& setup, const CameraView& camera, float aspect);

// What the raymarch draws from: a view-projection (Vulkan clip space, depth 0..1), whether its
// near plane is at depth 1 (reversed Z), and the part of the targets the view covers.
struct RaymarchView {
  glm::mat4 view_projection{1.0f};
  bool reversed_z = false;
  VkRect2D viewport{};  // in the targets' pixels; its extent must not be empty
};

class RaymarchPass {
 public:
  // HostTargets: draw the liquid alone into host targets (see HostTargets) instead of a full frame.
  RaymarchPass(engine::vk::Context& context, const LiquidNode& node, ViewOutput output);

  struct Outputs {
    engine::graph::ImageHandle color;
    engine::graph::ImageHandle depth;
  };
  // With `targets` (a compositing pass), draws into them; otherwise into new images.
  Outputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const RenderSettings& settings,
                 const RaymarchView& view, const HostTargets* targets = nullptr);

  static constexpr int k_brick_cells = 8;  // occupancy block edge, in grid cells

 private:
  const LiquidNode& node_;
  GridLayout bricks_;  // the occupancy grid, stored like the node's grids
  engine::vk::GraphicsPipeline occupancy_;
  CoarseMarch coarse_;
  engine::vk::GraphicsPipeline raymarch_;
  engine::vk::Context& context_;
  // Compositing: one pipeline per host colour format, depth format and depth convention, made on
  // first use.
  struct CompositeKey {
    VkFormat color;
    VkFormat depth;
    bool reversed_z;
    auto operator<=>(const CompositeKey&) const = default;
  };
  std::map<CompositeKey, std::unique_ptr<engine::vk::GraphicsPipeline>> composite_pipelines_;
  engine::vk::GraphicsPipeline background_;  // BACKGROUND_ONLY, for the tiles without liquid; not when compositing
  engine::vk::GraphicsPipeline tank_frame_;  // the domain box's edges over the frame; not when compositing
  engine::vk::Sampler linear_;
  engine::vk::Sampler nearest_;
  ViewUniforms uniforms_;
  bool composite_ = false;
  std::unique_ptr<MeshDrawPass> meshes_;  // the scene's mesh obstacles, drawn first (not when compositing)
};

}  // namespace liquid
