// Per-step health of a simulation, computed on the CPU from read-back particles and density:
// what the physics must conserve and respect (count and mass, finite state, walls and obstacles
// not crossed) and energy, so an unstable run is reported instead of silently continued.
#pragma once

#include "liquid/physics/obstacles.h"
#include "liquid/physics/setup.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace liquid {

// Computes the diagnostics of a snapshot; `density_ratio` is the grid's rho / rho0 (may be empty).
Diagnostics compute_diagnostics(const Scene& scene, const SimulationSetup& setup, const ParticleSnapshot& particles,
                                const std::vector<float>& density_ratio,
                                const std::vector<ObstaclePose>& obstacle_poses, int step, double time);

// The kinetic energy above which a run counts as unstable: `factor` times the energy the scene
// could release (potential energy over the domain height, plus initial and emitter motion).
double kinetic_energy_bound(const Scene& scene, const SimulationSetup& setup, double factor = 20.0);

// Throws SimulationError naming the step when particles are not finite or the energy is past `bound`.
void check_stable(const Diagnostics& diagnostics, double energy_bound);

}  // namespace liquid
