// The liquid's force and torque on each dynamic obstacle over one step, reduced on the raster
// pipeline by additive blending into the obstacle's texel of two 1 x N RGBA32F targets, two draws
// per dynamic obstacle: its pressure, the reaction of the liquid's energy to the body's kernel
// coverage from the cells' pressure P of the splat-adjoint pressure pass (a point per grid cell;
// shaders/liquid/solver/body_force.vert), and the opposite of the momentum its no-inflow condition
// gives the liquid it runs into (a point per particle; body_exchange.vert).
// The active region (active_region.h) needs no margin for them: the pressure read is non-zero only
// where the splat is (the bodies add no artificial density), the exchange reads the splat at the
// particles' own cells, and the region holds both exactly (a test compares bodies and particles
// with and without it).
#pragma once

#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/images.h"
#include "liquid/solver/variant.h"

#include <cstdint>
#include <vector>

namespace liquid {

struct BodyForceImages {
  ImageHandle force;   // texel (0, i): N on obstacle i
  ImageHandle torque;  // texel (0, i): N m about its centre
};

class BodyForcePass {
 public:
  // For the scene's dynamic obstacles.
  BodyForcePass(engine::vk::Context& context, const SolverVariant& variant, const Scene& scene,
                const SimulationSetup& setup, const std::vector<int32_t>& specialization);

  // From the step's splat (the velocity arriving at the bodies), its cells' pressure P
  // (PressurePass), the particles before their update (the first `active`) and the body state the
  // grid pass read (with the body shapes).
  BodyForceImages add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                         const StepImages& step, int active) const;

 private:
  engine::vk::GraphicsPipeline pressure_;  // a point per cell
  engine::vk::GraphicsPipeline exchange_;  // a point per particle
  engine::vk::Sampler nearest_;
  engine::vk::Sampler linear_;  // the body shapes'
  std::vector<int> dynamic_obstacles_;  // their indices
  uint32_t obstacles_ = 0;
  uint32_t cells_ = 0;
  float particle_mass_ = 0.0f;
  bool projection_ = false;  // the force from the projection's p, no exchange pass
};

}  // namespace liquid
