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

// The speed of a fall from rest across the domain's longest side, sqrt(2 |g| L), m/s: the fastest
// flow gravity alone gives (0 in shallow water, whose plane is horizontal).
double fall_speed(const SimulationSetup& setup);

// The step a scene runs at, s: its time_step, or (time_step 0, the default) its regime's acoustic
// CFL step at its own cell size, regime_acoustic_cfl h / c0 with c0 the speed of sound at rest, as
// the shipped scenes choose theirs (with no stiffness, no sound: a velocity CFL of 0.4 for the fall).
double scene_time_step(const Scene& scene);

// The longest fixed step stable in the setup's regime, s: stable_acoustic_cfl h / (c0 + fall_speed),
// sound and the fastest fall together (the bound runtime_parameter_range keeps the sliders in).
// make_setup refuses a fixed step past it.
double largest_stable_time_step(const SimulationSetup& setup);

// The live parameters (LiquidNode::set_runtime_parameters) a host's sliders can offer while the
// node keeps its step `time_step`, all of which stay stable (the viewer's panel uses them). Two
// conditions bound gravity g and stiffness k together, with L the domain's longest side:
//   hydrostatic: |g| L <= k_max_hydrostatic_ratio k: the pressure rho0 |g| L of a column across
//     the domain, in any direction, stays that fraction of k rho0, so the liquid stays weakly
//     compressed and its fall speed sqrt(2 |g| L) well below the speed of sound sqrt(k gamma);
//   step: sqrt(k gamma) + sqrt(2 |g| L) <= stable_acoustic_cfl h / dt: sound and the fastest fall
//     together within the regime's stable acoustic CFL (with no flow, the stiffest k the step
//     allows).
// The range of each is what both allow at the other's present value; the PIC ratio may be all of
// [0, 1]. The shipped scenes' own |g| L / k lies between 0.29 (column_*) and 0.70
// (dam_break_3d); 0.7 admits each scene's gravity at its stiffness (dam_break_2d: up to
// 15.4 m/s^2 at its k = 22.05, half the old slider's end of 30 m/s^2).
inline constexpr double k_max_hydrostatic_ratio = 0.7;
RuntimeParameterRange runtime_parameter_range(const SimulationSetup& setup, double time_step, float stiffness,
                                              glm::vec3 gravity);

// min(largest, acoustic bound, velocity bound) for the state in `d` (its max_speed and
// max_density_ratio).
double cfl_time_step(const SimulationSetup& setup, const AdaptiveTimeStep& cfl, const Diagnostics& d, double largest);

}  // namespace liquid
