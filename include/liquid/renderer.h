// LiquidRenderer: draws a LiquidNode's state on the host's render graph, after the solver's
// passes: a raymarch of the density volume (3D), the density field as liquid (2D) or a lit
// height field (shallow water); then FXAA. Outputs are graph images the host composites or reads.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/passes/fxaa.h"
#include "liquid/camera.h"
#include "liquid/node.h"

#include <map>
#include <memory>
#include <optional>

namespace engine::vk {
class Context;
}

namespace liquid {

// What every view writes (the FXAA pass reads the colour in the same format): RGBA8 colour and,
// where the view has depth, D32 depth.
constexpr VkFormat k_color_format = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat k_depth_format = VK_FORMAT_D32_SFLOAT;

struct RenderSettings {
  uint32_t width = 1024;   // the paper's frame: 1024 x 768
  uint32_t height = 768;
  float iso_level = k_default_iso_level;  // surface where rho / rho0 crosses this value
  // FXAA after the view. Empty: on for the renderer's own frame, off when compositing into a
  // host's targets (a host runs its own anti-aliasing after its whole scene, TAA for one); on when
  // compositing, its output lands in the host's colour target, which then needs
  // VK_IMAGE_USAGE_TRANSFER_SRC_BIT (the composite is copied out to be read) and a display-referred
  // format (not HDR: anti-aliasing belongs after the host's tone map).
  std::optional<bool> fxaa;
  bool draw_particles = false;  // 2D views: the particles as points over the liquid
  // 3D: draw into the host's own colour and depth targets (add_to with HostTargets) instead of a
  // frame of the renderer's own with its floor, sky and tank.
  bool composite = false;
  // Compositing into an HDR target (R16G16B16A16_SFLOAT, B10G11R11_UFLOAT_PACK32): the liquid's
  // linear radiance is multiplied by this, in the host's units before its tone mapping.
  float exposure = 1.0f;
  // 3D views of a scene with whitewater: spray, foam and bubbles drawn over the liquid (the
  // simulation runs them either way).
  bool whitewater = true;
};

// A host's own targets for compositing (RenderSettings::composite): its colour and depth images at
// the renderer's size. The colour may be R8G8B8A8 or B8G8R8A8, UNORM (the liquid's colour
// display-encoded) or SRGB (linear, the hardware encodes it), A2B10G10R10_UNORM, or the HDR
// R16G16B16A16_SFLOAT and B10G11R11_UFLOAT (linear radiance times RenderSettings::exposure). The
// depth may be D32_SFLOAT, D24_UNORM_S8_UINT or D32_SFLOAT_S8_UINT; a stencil is left as it was
// (the graph keeps such an image in DEPTH_STENCIL_ATTACHMENT_OPTIMAL). Both single-sampled: an MSAA
// host composites into its resolved colour and depth, after its resolve (a multisampled target is
// refused, naming it). Both are imported into the graph with their contents
// (engine::vk::Image::wrap + RenderGraph::import_image). The liquid is blended over the colour
// where its surface is nearer than the host's depth, and writes its own depth there, so host
// geometry in front hides the liquid and the host's later passes see the liquid's depth. A
// pipeline per colour format, depth format and depth convention is made on first use and kept.
struct HostTargets {
  engine::graph::ImageHandle color;
  engine::graph::ImageHandle depth;
};

// A host's own view of the liquid, for compositing: its view and projection matrices (Vulkan clip
// space, y down, depth 0..1), whatever projection the host uses: perspective or orthographic, a
// finite or an infinite far plane, jittered for TAA. `model` places the liquid's frame (metres, the
// domain [0, domain], y up) in the host's world: a rotation, a translation and a uniform scale;
// empty, the node's placement (LiquidNode::set_placement, which also maps the positions, brushes
// and read-backs a host gives or asks for in liquid::Frame::World). `reversed_z`: the projection
// maps the near plane to depth 1 (the host clears depth to 0 and keeps the greater depth; the
// liquid tests and writes its depth the same way). `viewport`: the rectangle of the targets the
// view fills (empty: all of it), so several views (split screen) composite one simulation step into
// one target, one add_to each.
struct HostView {
  std::optional<glm::mat4> model;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  bool reversed_z = false;
  VkRect2D viewport{};
};

// A rectangle of a host's colour target (R8G8B8A8_UNORM, imported into the graph) that a 2D liquid
// is drawn into (RenderSettings::composite on a 2D scene): the domain fitted into the rectangle,
// the liquid and the obstacles alone, blended by their coverage over what the host drew there (a
// panel, a HUD element, a texture the host then samples). The host's pixels outside the rectangle,
// and inside it where there is no liquid, are left as they were. `background`: the library's own
// background, letterbox and tank walls too, the rectangle opaque (the 2D view as in its own frame).
struct HostPanel {
  engine::graph::ImageHandle color;
  VkRect2D rect{};
  bool background = false;
};

struct RenderOutputs {
  engine::graph::ImageHandle color;  // RGBA8, before FXAA
  engine::graph::ImageHandle depth;  // D32 (3D views), metric depth of the first surface hit
  engine::graph::ImageHandle final;  // RGBA8 after FXAA (== color when FXAA is off, and when
                                     // compositing, where both are the host's colour, after FXAA)
};

class RaymarchPass;
class View2dPass;
class HeightFieldPass;
class WhitewaterDraw;

class LiquidRenderer {
 public:
  // Throws ArgumentError when the size exceeds the device's 2D image limit, UsageError for
  // RenderSettings::composite with shallow water. Each add_to() below throws UsageError when it does
  // not match how the renderer was made (composite or not, a 2D or 3D scene).
  LiquidRenderer(engine::vk::Context& context, const LiquidNode& node, const RenderSettings& settings);
  ~LiquidRenderer();

  RenderOutputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const CameraView& camera);
  // Composites into the host's targets (3D scenes, RenderSettings::composite); `color` (== `final`)
  // and `depth` of the result are the targets' new versions, after FXAA where it is on.
  RenderOutputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const CameraView& camera,
                       const HostTargets& targets);
  // A 2D scene's liquid into a rectangle of the host's colour target (see HostPanel); `color` and
  // `final` of the result are the target's new version. Throws ArgumentError for a
  // rectangle outside the target or a target of another format.
  RenderOutputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const HostPanel& panel);
  // The same from the host's own view (see HostView); the host draws its geometry with the same
  // matrices. Throws ArgumentError for a viewport outside the targets.
  RenderOutputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const HostView& view,
                       const HostTargets& targets);
  const RenderSettings& settings() const { return settings_; }

  // The view-projection (Vulkan clip space, y down, depth 0..1) the 3D view uses for `camera` at
  // the renderer's aspect ratio: a host compositing with depth through the library's camera draws
  // its geometry with this matrix so that its depths and the liquid's agree.
  glm::mat4 view_projection(const CameraView& camera) const;

 private:
  const LiquidNode& node_;
  RenderSettings settings_;
  std::unique_ptr<RaymarchPass> raymarch_;
  std::unique_ptr<View2dPass> view2d_;
  std::unique_ptr<HeightFieldPass> height_field_;
  std::unique_ptr<WhitewaterDraw> whitewater_;  // 3D scenes with whitewater, RenderSettings::whitewater
  std::unique_ptr<engine::passes::FxaaPass> fxaa_;  // the renderer's own frame; whether FXAA is on
  std::map<VkFormat, std::unique_ptr<engine::passes::FxaaPass>> composite_fxaa_;  // per host colour format
};

}  // namespace liquid
