// The graph images the solver's passes hand each other within a step, and the engine names every
// pass of liquid/ (solver and views) declares itself with.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"

#include <array>

namespace liquid {

using engine::graph::Access;
using engine::graph::ImageHandle;
using engine::graph::PassBuilder;
using engine::graph::PassContext;
using engine::vk::DescriptorKind;

struct SolverVariant;

struct ParticleImages {
  ImageHandle positions;   // RGBA32F, xyz m, w 1 when active
  ImageHandle velocities;  // RGBA32F, xyz m/s
  // The affine transfer's C_p (RGBA32F, 1/s): variant.affine_textures() of them, the rest invalid.
  std::array<ImageHandle, 3> affine{};
};

// The secondary particles' textures (liquid/solver/whitewater.h).
struct WhitewaterImages {
  ImageHandle positions;   // RGBA32F, xyz m, w the kind
  ImageHandle velocities;  // RGBA32F, xyz m/s, w the birth time
};

struct GridImages {
  ImageHandle velocity;    // (u', fluid flag)
  ImageHandle density;     // rho / rho0
  ImageHandle correction;  // the pressure projection's density correction, -grad psi (m), a transient
};

// The splat-adjoint pressure's grids (liquid/solver/pressure.h): the cells' pressure P, the
// potential Phi's image, and with dynamic bodies under the separable splat a third image, so the
// spread leaves P for the body force pass. `phi` is whichever holds Phi after the step's passes.
struct PressureImages {
  ImageHandle pressure, potential, scratch;
  ImageHandle phi;
  ImageHandle system;  // the pressure projection's per cell: (h^2 div u* / dt, the diagonal's weight,
                       // the density correction's right side, the liquid fraction)
};

// One step's images, as the passes leave them: the splat stage writes `splat` (and `region`), the
// pressure stage `pressure`, the grid pass `grids`, the body passes `bodies`, the particle pass the
// next particles. Which images a step has follows from the solver's variant.
struct StepImages {
  ParticleImages particles;         // the particles at the step's start
  ParticleImages particle_targets;  // the other textures of the ping-pong pair
  ImageHandle splat;                // (sum w u, sum w)
  ImageHandle deposit;              // the separable splat's deposit before its spreads (3D: lower slices)
  ImageHandle deposit_upper;        // 3D: the deposit's upper slices' shares
  ImageHandle region;               // the step's active region (variant.active_region)
  PressureImages pressure;          // variant.splat_adjoint()
  GridImages grids;
  ImageHandle bodies;               // the dynamic obstacles' state (a row of texels even without them)
  ImageHandle body_targets;         // the other texture of the body state's pair
  ImageHandle body_shapes;          // the dynamic meshes' distance (1 x 1 x 1 without them)
  ImageHandle mesh_field;           // the static meshes' field (variant.meshes)
};

// std::logic_error naming the image when `images` lacks one the variant needs or has one it does not.
void check_step_images(const StepImages& images, const SolverVariant& variant);

}  // namespace liquid
