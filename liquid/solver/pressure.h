// The splat-adjoint pressure (scene key "pressure_force": "splat_adjoint"): two full-screen grid
// passes before the grid pass. The first writes every cell's pressure P (pressure.frag); the second
// smooths it with the splat's own kernel into Phi = W^T P (potential.frag), whose gradient the grid
// pass takes instead of P's. That makes the pressure force the gradient of the liquid's internal
// energy, which the chapter's gradient of P is not (docs/physics.md). With the separable splat the
// smoothing is that splat's own kernel too: one pass per axis (separable_blur.h) instead of
// potential.frag's gather over every cell within r.
// Shaders: shaders/liquid/solver/pressure.frag, potential.frag and separable_blur.frag.
#pragma once

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"
#include "liquid/solver/separable_blur.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace liquid {

// R32F: the cells' pressure and its smoothed potential, m^2/s^2.
constexpr VkFormat k_pressure_format = VK_FORMAT_R32_SFLOAT;

class PressurePass {
 public:
  // `active_region`: its passes compute the step's active region only (active_region.h).
  PressurePass(engine::vk::Context& context, const GridLayout& layout, SplatMode splat,
               const std::vector<int32_t>& specialization, bool meshes, bool active_region);

  // Grid-sized descriptions of the two intermediate images (the node creates them as transients).
  engine::vk::ImageDesc image_desc() const { return desc_; }

  // Reads `splat` and the body state `bodies` with `body_shapes` (the dynamic bodies' kernel coverage), writes P into
  // `pressure` and smooths it into Phi (the handles are advanced to their new versions); returns
  // Phi, which is in `potential`, or in `pressure` for the separable splat's spread in 2D (its
  // passes alternate between the two images). With a valid `scratch` (a third such image) the
  // spread alternates between `potential` and it instead and P stays in `pressure`, for the body
  // force pass. `region`: the step's active region (valid exactly when the pass was made for one).
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle splat,
                     ImageHandle bodies, ImageHandle body_shapes, ImageHandle& pressure, ImageHandle& potential, ImageHandle& scratch,
                     ImageHandle mesh_field, ImageHandle region) const;

 private:
  engine::vk::GraphicsPipeline pressure_;
  std::optional<engine::vk::GraphicsPipeline> potential_;  // the point-sprite splat's gather
  std::optional<SeparableBlur> spread_;                     // the separable splat's passes
  engine::vk::Sampler nearest_;  // also the mesh field's (P reads the obstacles' density at cell centres)
  engine::vk::Sampler linear_;   // the body shapes'
  engine::vk::ImageDesc desc_;
  GridLayout layout_;
  bool active_region_ = false;
};

}  // namespace liquid
