// LiquidRenderer: draws a LiquidNode's state on the host's render graph, after the solver's
// passes: a raymarch of the density volume (3D), the density field as liquid (2D) or a lit
// height field (shallow water); then FXAA. Outputs are graph images the host composites or reads.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/passes/fxaa.h"
#include "liquid/node.h"
#include "liquid/render/camera.h"

#include <memory>

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
  float iso_level = 0.5f;  // surface where rho / rho0 crosses this value
  bool fxaa = true;
  bool draw_particles = false;  // 2D views: the particles as points over the liquid
};

struct RenderOutputs {
  engine::graph::ImageHandle color;  // RGBA8, before FXAA
  engine::graph::ImageHandle depth;  // D32 (3D views), metric depth of the first surface hit
  engine::graph::ImageHandle final;  // RGBA8 after FXAA (== color when FXAA is off)
};

class RaymarchPass;
class View2dPass;
class HeightFieldPass;

class LiquidRenderer {
 public:
  // Throws std::invalid_argument when the size exceeds the device's 2D image limit.
  LiquidRenderer(engine::vk::Context& context, const LiquidNode& node, const RenderSettings& settings);
  ~LiquidRenderer();

  RenderOutputs add_to(engine::graph::RenderGraph& graph, const LiquidImages& images, const CameraView& camera);
  const RenderSettings& settings() const { return settings_; }

 private:
  const LiquidNode& node_;
  RenderSettings settings_;
  std::unique_ptr<RaymarchPass> raymarch_;
  std::unique_ptr<View2dPass> view2d_;
  std::unique_ptr<HeightFieldPass> height_field_;
  std::unique_ptr<engine::passes::FxaaPass> fxaa_;
};

}  // namespace liquid
