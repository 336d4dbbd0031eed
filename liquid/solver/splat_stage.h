// The step's first stage, where the method varies (the scene's "splat"): the particles on the grid
// (section 3: rgb = sum w u, a = sum w), by the chapter's point sprites (splat.h) or the separable
// splat (separable_splat.h), and in 3D the step's active region from where they landed
// (active_region.h).
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace liquid {

class SplatStage {
 public:
  virtual ~SplatStage() = default;
  // Splats the first `active` of `step.particles` into `step.splat` (cleared first) and sets
  // `step.region` to the step's active region (left invalid when the variant has none).
  virtual void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step,
                      int active) const = 0;
};

// The variant's splat, into a grid of `splat_format`.
std::unique_ptr<SplatStage> make_splat_stage(engine::vk::Context& context, const SolverVariant& variant,
                                             const SimulationSetup& setup, VkFormat splat_format,
                                             const std::vector<int32_t>& specialization);

}  // namespace liquid
