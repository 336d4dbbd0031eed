// The separable splat (scene key "splat": "separable"): the same grid as the chapter's splat
// (section 3: rgb = sum w u, a = sum w), in two stages. Deposit: each active particle drawn as a
// point of two cells (once on each of the two slices around it in 3D) that adds its bilinear
// (trilinear) weights to the 2^d cells around it by additive blending. Spread: one full-screen pass
// per axis with the kernel's 1D taps (separable_blur.h). The kernel becomes the product of the
// axes' profiles (liquid/physics/kernel.h) and every particle draws 2^(d-2) points of 2 x 2 pixels
// instead of ceil(2r)^(d-2) points of 2r x 2r: on lavapipe, where the splat's cost is per point and
// per 4x4 block a point touches, a fraction of the chapter's (docs/physics.md, "The separable
// splat"). Shaders: shaders/liquid/solver/deposit.vert, deposit.frag (splat.geom on the
// geometry-shader path) and separable_blur.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"
#include "liquid/solver/separable_blur.h"

#include <cstdint>
#include <vector>

namespace liquid {

class SeparableSplatPass {
 public:
  SeparableSplatPass(engine::vk::Context& context, const GridLayout& layout, VkFormat splat_format,
                     const std::vector<int32_t>& specialization);

  // Writes the splat of the first `active_particles` particles into `splat` (every texel), using a
  // transient grid image for the deposit and the passes between.
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                     const ParticleImages& particles, ImageHandle splat, int active_particles) const;

 private:
  engine::vk::GraphicsPipeline deposit_;
  SeparableBlur spread_;
  engine::vk::Sampler nearest_;
  engine::vk::ImageDesc scratch_desc_;
  uint32_t instances_;  // points per particle: 1 in 2D, one per slice around it in 3D
};

}  // namespace liquid
