// Section 4, the grid pass: one full-screen pass over the grid (one layer per slice in 3D) that
// turns the splat into density and pressure, takes the pressure's finite-difference gradient, adds
// gravity, external forces and the obstacles' pressure, and enforces the walls.
// Shader: shaders/liquid/solver/grid.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

class GridPass {
 public:
  // `active_region`: it computes the step's active region only (active_region.h).
  GridPass(engine::vk::Context& context, const SimulationSetup& setup, const GridLayout& layout,
           const std::vector<int32_t>& specialization, bool meshes, bool active_region);

  // Reads `splat` (and, with the splat-adjoint pressure, PressurePass's `potential`) and the body
  // state `bodies` (dynamic obstacles' poses) with `body_shapes` (liquid/solver/body_shapes.h), writes the updated velocity (u', fluid flag) and
  // rho / rho0 into `grids`. With mesh obstacles (`meshes`), reads their field
  // (liquid/solver/mesh_field.h). `region`: the step's active region (valid exactly when the pass
  // was made for one).
  GridImages add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle splat,
                    ImageHandle bodies, ImageHandle body_shapes, const GridImages& grids, ImageHandle potential, ImageHandle mesh_field,
                    ImageHandle region) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;  // also the mesh field's: read at cell centres (a linear sampler made
                                 // lavapipe's fetches from it four times slower)
  engine::vk::Sampler linear_;   // the body shapes'
  bool splat_adjoint_ = false;
  GridLayout layout_;
  bool active_region_ = false;
};

}  // namespace liquid
