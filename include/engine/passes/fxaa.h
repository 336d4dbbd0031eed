// FXAA as a generic graph pass any host can add: input image -> new anti-aliased image of the
// same size and format (after Granite's add_fxaa). Knows nothing of what the input shows. Two
// passes: "NAME.mark" copies every pixel and marks the 2x2 quads that hold an edge in a depth
// image; "NAME" runs FXAA behind the early depth test, on the marked quads alone.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"

#include <string>

namespace engine::passes {

struct FxaaSettings {
  float edge_threshold = 0.125f;       // relative contrast below which a pixel is left alone
  float edge_threshold_min = 0.0312f;  // absolute contrast floor (dark areas)
  float subpixel_quality = 0.75f;      // sub-pixel aliasing removal, 0..1
};

class FxaaPass {
 public:
  // `format`: the colour format of the images this pass will read and write (e.g. RGBA8 UNORM).
  FxaaPass(vk::Context& context, VkFormat format);

  // Reads `input` in the fragment shader, writes and returns a new transient image.
  graph::ImageHandle add_to(graph::RenderGraph& graph, graph::ImageHandle input,
                            const FxaaSettings& settings = {}, const std::string& name = "fxaa") const;
  // The same into `output` (a 2D image of the pass's format and the input's size, not the input):
  // a host's own target, for instance. Returns its new version.
  graph::ImageHandle add_to(graph::RenderGraph& graph, graph::ImageHandle input, graph::ImageHandle output,
                            const FxaaSettings& settings = {}, const std::string& name = "fxaa") const;

 private:
  vk::GraphicsPipeline mark_;      // pass one: the copy, and the quads with an edge marked in depth
  vk::GraphicsPipeline pipeline_;  // pass two: FXAA on the marked quads only
  vk::Sampler sampler_;
  VkFormat format_;
};

}  // namespace engine::passes
