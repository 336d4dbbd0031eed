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
#include "liquid/solver/images.h"
#include "liquid/solver/separable_blur.h"
#include "liquid/solver/variant.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace liquid {

// R32F: the cells' pressure and its smoothed potential, m^2/s^2.
constexpr VkFormat k_pressure_format = VK_FORMAT_R32_SFLOAT;
// RGBA32F: the pressure projection's system, one cell's rows of its two Poisson equations (the
// pressure's and the density correction's, which share the diagonal).
constexpr VkFormat k_projection_system_format = VK_FORMAT_R32G32B32A32_SFLOAT;
// RG32F: the pressure projection's solution (p in m^2/s^2, the density correction's psi in m^2).
constexpr VkFormat k_projection_pressure_format = VK_FORMAT_R32G32_SFLOAT;
constexpr size_t k_projection_pressure_channels = 2;

class PressurePass {
 public:
  PressurePass(engine::vk::Context& context, const SolverVariant& variant, const std::vector<int32_t>& specialization);

  // The step's grids for P and Phi, transients of `graph` (StepImages::pressure): with dynamic
  // bodies under the separable splat a third, so that P is still there for the body force pass.
  PressureImages create_images(engine::graph::RenderGraph& graph) const;

  // Reads the step's splat, the body state with the body shapes, the mesh field and the active
  // region; writes P into `step.pressure.pressure` and sets `step.pressure.phi` to the image that
  // holds Phi (the potential's, or P's own in 2D under the separable splat, whose spread alternates
  // between the two images, unless there is a scratch image).
  // The pressure projection's solution, kept from step to step (checkpoints save it); null without.
  engine::vk::Image* projection_pressure() const { return projection_pressure_ ? &*projection_pressure_ : nullptr; }

  // `stepping` false: a grid pass for the view (dt 0), which leaves the projection's p as it is.
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
              bool stepping = true) const;

 private:
  engine::vk::GraphicsPipeline pressure_;
  std::optional<engine::vk::GraphicsPipeline> potential_;  // the point-sprite splat's gather
  std::optional<SeparableBlur> spread_;                     // the separable splat's passes
  // The pressure projection (variant.projection()): the divergence, one Jacobi iteration, and its
  // solution, kept from step to step as the next step's first iterate.
  std::optional<engine::vk::GraphicsPipeline> divergence_, jacobi_;
  mutable std::optional<engine::vk::Image> projection_pressure_;  // imported (written) by const declarations
  void add_projection_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                         StepImages& step, bool stepping) const;
  engine::vk::Sampler nearest_;  // also the mesh field's (P reads the obstacles' density at cell centres)
  engine::vk::Sampler linear_;   // the body shapes'
  SolverVariant variant_;
};

}  // namespace liquid
