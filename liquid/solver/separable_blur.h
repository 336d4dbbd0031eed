// One full-screen grid pass per axis that spreads a grid with the splat kernel's 1D taps
// (shaders/liquid/solver/separable_blur.frag): the separable splat's second stage, and the separable
// splat's adjoint potential (with the walls' hydrostatic ghost rise, normalised).
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

class SeparableBlur {
 public:
  enum class Kind {
    Splat,      // (sum w u, sum w) spread unnormalised along x and y (SeparableSplatPass runs z)
    Potential,  // Phi = W^T P along every axis: normalised, hydrostatic ghost cells beyond the walls
  };
  // The images the passes write in turn (first, second, first ...), each pass reading the last one's
  // output; add_to() advances both to their newest versions.
  struct Targets {
    ImageHandle first, second;
  };

  SeparableBlur(engine::vk::Context& context, const SolverVariant& variant, Kind kind, VkFormat format,
                const std::vector<int32_t>& specialization);

  // Spreads `input` along x, then y (then z) through `targets` (grid images of the blur's format,
  // either of which may be `input` itself) and returns the one that holds the result. `region`: the
  // step's active region (valid exactly when the variant has one).
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle input,
                     Targets& targets, ImageHandle region) const;

  // How many passes add_to declares: one per axis it spreads.
  int passes() const { return int(axes_.size()); }

 private:
  std::vector<engine::vk::GraphicsPipeline> axes_;
  engine::vk::Sampler nearest_;
  SolverVariant variant_;
};

}  // namespace liquid
