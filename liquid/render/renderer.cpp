#include "liquid/renderer.h"

#include "engine/graph/transfer.h"
#include "engine/vk/context.h"
#include "liquid/render/height_field.h"
#include "liquid/render/raymarch.h"
#include "liquid/render/view2d.h"
#include "liquid/render/whitewater_draw.h"
#include "liquid/solver/node_view.h"
#include "shaders/liquid/render/view_blocks.h"

#include <stdexcept>
#include <string>

namespace liquid {

LiquidRenderer::LiquidRenderer(engine::vk::Context& context, const LiquidNode& node, const RenderSettings& settings)
    : node_(node), settings_(settings) {
  const uint32_t limit = context.limits().maxImageDimension2D;
  if (settings.width == 0 || settings.height == 0 || settings.width > limit || settings.height > limit)
    throw ArgumentError("frame size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " is outside the device's limit of 1.." + std::to_string(limit) + " pixels per side");
  const SimulationSetup& setup = node_setup(node);
  const ViewOutput output = settings.composite ? ViewOutput::HostTargets : ViewOutput::OwnFrame;
  if (setup.shallow_water)
    height_field_ = std::make_unique<HeightFieldPass>(context, node);
  else if (setup.dimension == 3)
    raymarch_ = std::make_unique<RaymarchPass>(context, node, output);
  else
    view2d_ = std::make_unique<View2dPass>(context, node, output);
  if (raymarch_ && settings.whitewater && node.scene().whitewater)
    whitewater_ = std::make_unique<WhitewaterDraw>(context, node);
  if (settings.composite && height_field_)
    throw UsageError("liquid: shallow water is not composited into host targets (3D and 2D liquids are)");
  if (settings.fxaa.value_or(!settings.composite))
    fxaa_ = std::make_unique<engine::passes::FxaaPass>(context, k_color_format);
}

glm::mat4 LiquidRenderer::view_projection(const CameraView& camera) const {
  return raymarch_view_projection(node_setup(node_), camera, float(settings_.width) / float(settings_.height));
}

LiquidRenderer::~LiquidRenderer() = default;

RenderOutputs LiquidRenderer::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                     const CameraView& camera, const HostTargets& targets) {
  // The library's camera looks at the liquid's own frame.
  return add_to(graph, images, HostView{.model = glm::mat4(1.0f), .projection = view_projection(camera)}, targets);
}

RenderOutputs LiquidRenderer::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                     const HostPanel& panel) {
  if (!settings_.composite || !view2d_)
    throw UsageError("liquid: a host panel needs a compositing renderer of a 2D scene");
  const engine::vk::ImageDesc& d = graph.image_desc(panel.color);
  const VkRect2D r = panel.rect;
  if (d.kind != engine::vk::ImageKind::Image2D || d.format != k_color_format)
    throw ArgumentError("liquid: the host's panel target '" + graph.image_name(panel.color) +
                        "' must be a 2D R8G8B8A8_UNORM image");
  if (r.extent.width == 0 || r.extent.height == 0 || r.offset.x < 0 || r.offset.y < 0 ||
      r.offset.x + r.extent.width > d.width || r.offset.y + r.extent.height > d.height)
    throw ArgumentError("liquid: the panel " + std::to_string(r.extent.width) + "x" +
                        std::to_string(r.extent.height) + " at (" + std::to_string(r.offset.x) + ", " +
                        std::to_string(r.offset.y) + ") is not inside the host's target '" +
                        graph.image_name(panel.color) + "'");
  if (fxaa_)
    throw UsageError("liquid: FXAA is not run on a host panel (RenderSettings::fxaa = false)");
  RenderSettings frame = settings_;
  frame.width = d.width;
  frame.height = d.height;
  const engine::graph::ImageHandle color = view2d_->add_to(graph, images, frame, &panel);
  return {color, {}, color};
}

namespace {

// A host target's format, after checking it is a single-sampled 2D image of the renderer's size.
// An MSAA host resolves its scene first: the liquid is one surface per pixel, drawn into the
// resolved colour with the resolved depth (as a TAA or deferred engine's post-scene passes are).
VkFormat checked_target_format(const engine::graph::RenderGraph& graph, engine::graph::ImageHandle image,
                               const char* what, const RenderSettings& settings) {
  const engine::vk::ImageDesc& d = graph.image_desc(image);
  const std::string target = std::string("liquid: the host's ") + what + " target '" + graph.image_name(image) + "'";
  if (d.kind != engine::vk::ImageKind::Image2D || d.width != settings.width || d.height != settings.height)
    throw ArgumentError(target + " must be a " + std::to_string(settings.width) + "x" +
                        std::to_string(settings.height) + " 2D image");
  if (d.samples != VK_SAMPLE_COUNT_1_BIT)
    throw ArgumentError(target + " has " + std::to_string(int(d.samples)) +
                        " samples; composite into the resolved single-sample colour and depth");
  return d.format;
}

[[noreturn]] void refuse_format(const engine::graph::RenderGraph& graph, engine::graph::ImageHandle image,
                                const char* what, const std::string& why) {
  throw ArgumentError(std::string("liquid: the host's ") + what + " target '" + graph.image_name(image) +
                      "' has format " + std::to_string(int(graph.image_desc(image).format)) + ", " + why);
}

}  // namespace

RenderOutputs LiquidRenderer::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                     const HostView& view, const HostTargets& targets) {
  if (!settings_.composite || !raymarch_) throw UsageError("liquid: add_to with host targets needs RenderSettings::composite");
  const VkFormat color_format = checked_target_format(graph, targets.color, "colour", settings_);
  if (!composite_output_encoding(color_format) ||
      !node_.context().format_supports(color_format, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT))
    refuse_format(graph, targets.color, "colour",
                  "which the liquid does not composite into (R8G8B8A8 or B8G8R8A8 UNORM or SRGB, A2B10G10R10_UNORM, "
                  "R16G16B16A16_SFLOAT or B10G11R11_UFLOAT, blendable on the device)");
  const VkFormat depth_format = checked_target_format(graph, targets.depth, "depth", settings_);
  if (!is_composite_depth_format(depth_format) ||
      !node_.context().format_supports(depth_format, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
    refuse_format(graph, targets.depth, "depth",
                  "which the liquid does not test against (D32_SFLOAT, D24_UNORM_S8_UINT or D32_SFLOAT_S8_UINT, "
                  "a depth attachment on the device)");
  // FXAA works on display-referred colour: an HDR target is the host's to tone map first.
  if (fxaa_ && composite_output_encoding(color_format) == LIQUID_OUTPUT_HDR)
    throw UsageError("liquid: FXAA into the host's HDR colour target '" + graph.image_name(targets.color) +
                     "' would smooth radiance before its tone map; run anti-aliasing after it "
                     "(RenderSettings::fxaa = false)");
  engine::vk::ImageDesc copy_desc = graph.image_desc(targets.color);
  if (fxaa_ && !(copy_desc.usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
    throw UsageError("liquid: FXAA in the host's colour target '" + graph.image_name(targets.color) +
                     "' needs VK_IMAGE_USAGE_TRANSFER_SRC_BIT on it (or RenderSettings::fxaa = false)");
  const VkRect2D whole{{0, 0}, {settings_.width, settings_.height}};
  const glm::mat4 model = view.model.value_or(node_.placement().world_from_liquid());
  const RaymarchView raymarch_view{view.projection * view.view * model, view.reversed_z,
                                   view.viewport.extent.width == 0 && view.viewport.extent.height == 0 ? whole
                                                                                                      : view.viewport};
  RaymarchPass::Outputs r = raymarch_->add_to(graph, images, settings_, raymarch_view, &targets);
  if (whitewater_ && images.whitewater_positions.valid()) {
    const WhitewaterDraw::Targets drawn =
        whitewater_->add_to(graph, images, {r.color, r.depth}, raymarch_view.view_projection, raymarch_view.reversed_z,
                            raymarch_view.viewport, settings_.exposure);
    r = {drawn.color, drawn.depth};
  }
  RenderOutputs out{r.color, r.depth, r.color};
  if (fxaa_) {
    // FXAA reads what it writes around each pixel, so the composite is copied out and filtered
    // back into the host's target.
    copy_desc.usage = 0;
    const engine::graph::ImageHandle composite =
        engine::graph::add_copy(graph, r.color, graph.create_image("liquid.composite", copy_desc), "liquid.composite_copy");
    auto& pass = composite_fxaa_[color_format];  // a pipeline per host format, made once
    if (!pass) pass = std::make_unique<engine::passes::FxaaPass>(node_.context(), color_format);
    out.color = out.final = pass->add_to(graph, composite, graph.latest(r.color));
  }
  return out;
}

RenderOutputs LiquidRenderer::add_to(engine::graph::RenderGraph& graph, const LiquidImages& images,
                                     const CameraView& camera) {
  if (settings_.composite) throw UsageError("liquid: a compositing renderer draws into host targets");
  RenderOutputs out;
  if (raymarch_) {
    const RaymarchView own{view_projection(camera), false, {{0, 0}, {settings_.width, settings_.height}}};
    const RaymarchPass::Outputs r = raymarch_->add_to(graph, images, settings_, own);
    out.color = r.color;
    out.depth = r.depth;
    if (whitewater_ && images.whitewater_positions.valid()) {
      const WhitewaterDraw::Targets drawn = whitewater_->add_to(graph, images, {r.color, r.depth}, own.view_projection,
                                                                false, own.viewport, settings_.exposure);
      out.color = drawn.color;
      out.depth = drawn.depth;
    }
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
