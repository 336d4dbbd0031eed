// The separable splat (scene key "splat": "separable"): the same grid as the chapter's splat
// (section 3: rgb = sum w u, a = sum w) with the tensor-product kernel of liquid/physics/kernel.h,
// in two stages, one point per particle:
//   2D: each particle a point of 2 x 2 cells that adds its bilinear weights by additive blending,
//       then one full-screen pass per axis with the kernel's 1D taps (separable_blur.h).
//   3D: the same point in the slice below the particle, adding its bilinear weights to two grids,
//       that slice's share and the upper one's; a pass along z with the taps that also adds the
//       upper shares to their slices, then the x and y passes.
// The chapter's splat draws a point of 2r x 2r cells per slice the kernel reaches (6 for r = 3 in
// 3D), and on lavapipe a point's cost is mostly per point (docs/physics.md, "The separable splat").
// Shaders: shaders/liquid/solver/deposit.vert, deposit.frag (splat.geom on the geometry-shader
// path) and separable_blur.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/images.h"
#include "liquid/solver/separable_blur.h"
#include "liquid/solver/splat_stage.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace liquid {

class SeparableSplatPass : public SplatStage {
 public:
  SeparableSplatPass(engine::vk::Context& context, const SolverVariant& variant, VkFormat splat_format,
                     const std::vector<int32_t>& specialization);

  // The deposit, the active region from its marks (the spreads are trimmed to it), then the spread.
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
              int active) const override;

 private:
  // The first stage's grids: in 2D the deposit is in the splat itself; in 3D in `lower` and `upper`,
  // transient grids. `lower` marks every particle (the active region's marks).
  struct Deposit {
    ImageHandle lower, upper;
  };
  Deposit deposit(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, const StepImages& step,
                  int active) const;
  // Spreads the deposit into the splat (every texel; the region's, cleared elsewhere, with one).
  ImageHandle spread(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, const Deposit& deposit,
                     const StepImages& step) const;

  engine::vk::GraphicsPipeline deposit_;
  std::optional<engine::vk::GraphicsPipeline> spread_z_;  // 3D: the z pass over the deposit's two grids
  SeparableBlur spread_xy_;                               // the x and y passes
  engine::vk::Sampler nearest_;
  engine::vk::ImageDesc scratch_desc_;
  SolverVariant variant_;
  std::optional<ActiveRegion> active_region_;
};

}  // namespace liquid
