// Section 3, the splat: every active particle drawn once as a point (once per slice it reaches in
// 3D) and its kernel w = (1 - d^2/r^2)^3 accumulated by additive blending into the splat grid:
// rgb = sum w u, a = sum w. Shaders: shaders/liquid/solver/splat.vert, splat.frag (and splat.geom on
// the geometry-shader path, liquid/solver/grid_layout.h).
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/images.h"
#include "liquid/solver/splat_stage.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace liquid {

// A pipeline that draws one point per particle from the particle textures (the vertex stage reads
// them) and blends additively into `format`: the chapter's splat and the separable splat's deposit.
// On the geometry-shader path splat.geom routes each point to its slice. Under the affine transfer
// the vertex stage also reads the particles' C_p.
engine::vk::GraphicsPipelineDesc particle_points_pipeline(const char* name, const SolverVariant& variant,
                                                          std::span<const uint32_t> vertex,
                                                          std::span<const uint32_t> fragment, VkFormat format,
                                                          const std::vector<int32_t>& specialization);

// The particles' images bound for particle_points_pipeline()'s vertex stage.
void bind_particle_points(engine::passes::PassBindings& bindings, PassBuilder& builder, const ParticleImages& particles,
                          const engine::vk::Sampler& nearest);

class SplatPass : public SplatStage {
 public:
  SplatPass(engine::vk::Context& context, const SolverVariant& variant, const SimulationSetup& setup,
            VkFormat splat_format, const std::vector<int32_t>& specialization);

  // The splat, then the active region from its grid (whose marks already reach the kernel's radius).
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
              int active) const override;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;
  uint32_t instances_;  // draws per particle: 1 in 2D, one per slice the kernel can reach in 3D
  std::optional<ActiveRegion> active_region_;
};

}  // namespace liquid
