// The active region of a 3D step: most of a 3D grid holds no liquid (a pool on the floor, a jet
// through the air), and the full-screen grid passes (the separable splat's spreads, the pressure and
// potential passes, the grid pass) cost the same for an empty cell as for a full one. So after the
// step's particles are on the grid (the separable splat's deposit, or the point-sprite splat), two
// small passes reduce that grid's marks to one rectangle of cells per band of
// LIQUID_ACTIVE_REGION_BAND_ROWS rows of each slice: every marked cell of the slices and rows within
// `margin` of the band, widened by `margin` in x and y and kept within the band. The step's grid
// passes then draw those rectangles instead of whole slices (shaders/liquid/solver/
// active_region.vert) into targets cleared to zero first.
//
// Same results: a pass's value outside the region is what the whole-grid pass would have written,
// zero, wherever a later pass reads it (margin_cells() says why); the grid pass's velocity in a
// cell without liquid, which nothing reads (its fluid flag is 0), is zero there instead of its
// gravity step. A test runs the same scenes both ways and compares the particles bit for bit.
//   liquid.active_rows    one fragment per row (y, z): the span of marked x (active_rows.frag)
//   liquid.active_slices  one fragment per band of a slice: its rectangle (active_slices.frag)
// 2D grids (and so shallow water) are not trimmed: their passes cost little beside the splat's
// points, and two more passes with their barriers would cost about what they save.
#pragma once

#include "engine/passes/bindings.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

// How far past the marks the region must reach for the results to be exact, in cells, with r the
// kernel radius rounded up:
//   - the splat's spreads: the deposit's 2 x 2 (x 2) cells hold the particle, whose kernel reaches
//     r cells from it: r + 1 past the marks (the point-sprite splat's marks already include it: 0);
//   - the chapter's grid pass: one neighbour of every cell with liquid: + 1;
//   - the splat-adjoint pressure: the grid pass takes the potential at those neighbours, which
//     gathers the pressure r cells around them (the pressure is not zero outside the liquid near
//     obstacles): + r + 2;
//   - the pressure projection (`projection`, which takes the splat-adjoint key but spreads no
//     potential): the grid pass reads p and the liquid fractions at one neighbour of every cell
//     the particles read, and p is zero outside the liquid: + 1.
int active_region_margin_cells(const SimulationSetup& setup, bool projection);
// Bands of LIQUID_ACTIVE_REGION_BAND_ROWS rows per slice (the last may be shorter).
int active_region_bands(const GridLayout& layout);

class ActiveRegion {
 public:
  ActiveRegion(engine::vk::Context& context, const GridLayout& layout, const std::vector<int32_t>& specialization);

  // Declares the two reductions of `marks` (a grid whose alpha is non-zero where particles put
  // weight) and returns the rectangles: a bands x cells.z RGBA32F image, texel (band, z) =
  // (x0, y0, x1, y1).
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                     ImageHandle marks) const;

 private:
  engine::vk::GraphicsPipeline rows_, slices_;
  engine::vk::Sampler nearest_;
  engine::vk::ImageDesc rows_desc_, slices_desc_;
};

// For a grid pass's pipeline: its binding of the rectangles (nothing for the whole grid).
void add_active_region_binding(const SolverVariant& variant, std::vector<engine::vk::DescriptorBinding>& bindings);
// In a grid pass's setup: binds `region` (valid exactly when the pass was made with an active region,
// else std::logic_error) and returns how the pass's targets load: cleared to zero, since the
// region's draws leave the rest untouched, or not at all (whole grid).
engine::graph::AttachmentOptions bind_active_region(engine::passes::PassBindings& bindings, PassBuilder& builder,
                                                    ImageHandle region, bool active_region,
                                                    const engine::vk::Sampler& nearest);
// In its record: the slices' rectangles, or the whole grid.
void draw_grid_cells(const PassContext& ctx, const GridLayout& layout, bool active_region);

}  // namespace liquid
