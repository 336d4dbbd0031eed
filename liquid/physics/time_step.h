// Adaptive time steps: the largest step the CFL conditions allow for the state a diagnosis saw.
// The chapter's scheme is explicit and weakly compressible, so two conditions bound a step of
// length dt on cells of size h:
//   acoustic: dt <= C_a h / (c + |u|max), with c the speed of sound of P = k ((rho/rho0)^gamma - 1)
//             at the densest cell, c^2 = rho dP/drho = k gamma (rho/rho0)^gamma;
//   velocity: dt <= C_v h / |u|max (no particle crosses more than C_v cells per step).
// While c is several times the flow speed (the regime the chapter's stiffness is chosen for) the
// acoustic one binds, so adapting saves little time; it keeps a run stable when the liquid is
// compressed or fast beyond what a fixed step was chosen for.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/types.h"

namespace liquid {


// The acoustic CFL a scene of the setup's regime keeps to: the chapter's 0.16, or the long steps'
// 1.3 scaled by the kernel radius / 3 cells (the shortest waves it carries are a kernel wide).
double regime_acoustic_cfl(const SimulationSetup& setup);

// The largest acoustic CFL known stable in the setup's regime, for its kernel radius.
double stable_acoustic_cfl(const SimulationSetup& setup);

// Speed of sound (m/s) at density ratio rho / rho0.
double speed_of_sound(const SimulationSetup& setup, double density_ratio);

// min(largest, acoustic bound, velocity bound) for the state in `d` (its max_speed and
// max_density_ratio).
double cfl_time_step(const SimulationSetup& setup, const AdaptiveTimeStep& cfl, const Diagnostics& d, double largest);

}  // namespace liquid
