// The declaration every solver pass repeats, written once: a pass named after its pipeline, whose
// bindings start with the solver's uniform block; the pass binds its images and writes its targets
// in `declare`, and its record pushes the bindings before `draw`.
#pragma once

#include "engine/passes/bindings.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/images.h"
#include "liquid/solver/uniforms.h"
#include "liquid/solver/variant.h"

#include <utility>

namespace liquid {

// `declare(bindings, builder)` returns the pass's Outputs; `draw(ctx)` records its draws.
template <class Outputs, class Declare, class Draw>
Outputs add_solver_pass(engine::graph::RenderGraph& graph, const engine::vk::GraphicsPipeline& pipeline,
                        const engine::vk::UniformSlice& uniforms, Declare&& declare, Draw draw) {
  struct Data {
    engine::passes::PassBindings bindings;
    Outputs out;
  };
  return graph
      .add_pass<Data>(
          pipeline.name(),
          [&](PassBuilder& builder, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.out = declare(d.bindings, builder);
          },
          [draw = std::move(draw)](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            draw(ctx);
          })
      .out;
}

// Where a full-screen grid pass draws: every cell of the variant's grid, or the step's active
// region (`region`, valid exactly when the variant has one), read with `nearest`.
struct GridCells {
  const SolverVariant& variant;
  ImageHandle region;
  const engine::vk::Sampler& nearest;
};

// A full-screen pass over `cells`: `declare(bindings, builder, load)` writes its targets with `load`
// (cleared when only the active region is drawn, since the rest must read zero).
template <class Outputs, class Declare>
Outputs add_grid_cells_pass(engine::graph::RenderGraph& graph, const engine::vk::GraphicsPipeline& pipeline,
                            const engine::vk::UniformSlice& uniforms, const GridCells& cells, Declare&& declare) {
  return add_solver_pass<Outputs>(
      graph, pipeline, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& builder) {
        const engine::graph::AttachmentOptions load =
            bind_active_region(bindings, builder, cells.region, cells.variant.active_region, cells.nearest);
        return declare(bindings, builder, load);
      },
      [layout = cells.variant.layout, active_region = cells.variant.active_region](const PassContext& ctx) {
        draw_grid_cells(ctx, layout, active_region);
      });
}

}  // namespace liquid
