// Section 4, the grid pass: one full-screen pass over the grid (one layer per slice in 3D) that
// turns the splat into density and pressure, takes the pressure's finite-difference gradient, adds
// gravity, external forces and the obstacles' pressure, and enforces the walls. Under the pressure
// projection it also writes the density correction that moves the particles (projection.glsl).
// Shader: shaders/liquid/solver/grid.frag.
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

class GridPass {
 public:
  GridPass(engine::vk::Context& context, const SolverVariant& variant, const std::vector<int32_t>& specialization);

  // Reads the step's splat (and, with the splat-adjoint pressure, Phi), the body state with the body
  // shapes, the mesh field (with meshes) and the active region (with one); writes the updated
  // velocity (u', fluid flag) and rho / rho0 into `step.grids`.
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, StepImages& step) const;

  // Under the pressure projection the step's image for the density correction the pass also writes
  // (GridImages::correction), a transient of `graph`; an invalid handle without.
  ImageHandle create_correction(engine::graph::RenderGraph& graph) const;

 private:
  engine::vk::GraphicsPipeline pipeline_;
  engine::vk::Sampler nearest_;  // also the mesh field's: read at cell centres (a linear sampler made
                                 // lavapipe's fetches from it four times slower)
  engine::vk::Sampler linear_;   // the body shapes'
  SolverVariant variant_;
};

}  // namespace liquid
