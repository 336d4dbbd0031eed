// One full-screen grid pass per axis that spreads a grid with the splat kernel's 1D taps
// (shaders/liquid/solver/separable_blur.frag): the separable splat's second stage, and the separable
// splat's adjoint potential (with the walls' hydrostatic ghost rise, normalised).
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

class SeparableBlur {
 public:
  enum class Kind {
    Splat,      // (sum w u, sum w) spread unnormalised along x and y (SeparableSplatPass runs z)
    Potential,  // Phi = W^T P along every axis: normalised, hydrostatic ghost cells beyond the walls
  };
  // `active_region`: its passes compute the step's active region only (active_region.h).
  SeparableBlur(engine::vk::Context& context, const GridLayout& layout, Kind kind, VkFormat format,
                const std::vector<int32_t>& specialization, bool active_region);

  // Spreads `source` along x, then y (then z), each pass reading the other's output: source ->
  // scratch -> source (-> scratch). Both handles are advanced to their newest versions; returns the
  // one that holds the result: source after an even number of passes, scratch after an odd one.
  // Both must be grid images of the blur's format. `region`: the step's active region's rectangles
  // (valid exactly when the blur was made for one).
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle& source,
                     ImageHandle& scratch, ImageHandle region) const;
  // The same, leaving `source` as it is: source -> first -> second (-> first). Returns the one that
  // holds the result.
  ImageHandle add_to_keeping(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                             ImageHandle source, ImageHandle& first, ImageHandle& second, ImageHandle region) const;

  // How many passes add_to declares: one per axis it spreads.
  int passes() const { return int(axes_.size()); }

 private:
  // The passes from `input`, writing `first`, `second`, `first` ... in turn, each reading the last
  // one's output.
  ImageHandle chain(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle* input,
                    ImageHandle* first, ImageHandle* second, ImageHandle region) const;

  std::vector<engine::vk::GraphicsPipeline> axes_;
  engine::vk::Sampler nearest_;
  GridLayout layout_;
  bool active_region_ = false;
};

}  // namespace liquid
