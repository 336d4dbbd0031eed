#include "liquid/render/renderer.h"

#include "engine/vk/context.h"
#include "liquid/render/height_field.h"
#include "liquid/render/raymarch.h"
#include "liquid/render/view2d.h"

#include <stdexcept>
#include <string>

namespace liquid {

LiquidRenderer::LiquidRenderer(engine::vk::Context& context, const LiquidNode& node, const RenderSettings& settings)
    : node_(node), settings_(settings) {
  const uint32_t limit = context.limits().maxImageDimension2D;
  if (settings.width == 0 || settings.height == 0 || settings.width > limit || settings.height > limit)
    throw std::invalid_argument("frame size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                                " is outside the device's limit of 1.." + std::to_string(limit) + " pixels per side");
  const SimulationSetup& setup = node.setup();
  if (setup.shallow_water)
    height_field_ = std::make_unique<HeightFieldPass>(context, node);
  else if (setup.dimension == 3)
    raymarch_ = std::make_unique<RaymarchPass>(context, node);
  else
    view2d_ = std::make_unique<View2dPass>(context, node);
  if (settings.fxaa) fxaa_ = std::make_unique<engine::passes::FxaaPass>(context, k_color_format);
}

LiquidRenderer::~LiquidRenderer() = default;

RenderOutputs LiquidRenderer::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                     const CameraView& camera) {
  RenderOutputs out;
  if (raymarch_) {
    const RaymarchPass::Outputs r = raymarch_->add_to(graph, images, settings_, camera);
    out.color = r.color;
    out.depth = r.depth;
  } else if (height_field_) {
    out.color = height_field_->add_to(graph, images, settings_, camera);
  } else {
    out.color = view2d_->add_to(graph, images, settings_);
  }
  // FXAA on the same graph, after the view (section 7).
  out.final = fxaa_ ? fxaa_->add_to(graph, out.color) : out.color;
  return out;
}

}  // namespace liquid
