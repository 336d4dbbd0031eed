// Still water that keeps its volume: a pool at rest's free surface measured from its particles, and
// its density profile against hydrostatics. Pure CPU code, used by the validation tool
// (tools/liquid_validate/main.cpp, "still") and the tests.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/types.h"

#include <vector>

namespace liquid {

// The free surface's height from the particles (m): the top particle of each column two spacings
// wide in the middle 80 % of the tank along x, averaged, plus half a spacing (what
// tools/liquid_validate/pool_level.py measures). NaN with no particle there.
double particle_surface_level(const ParticleSnapshot& particles, double length, double spacing);

// The density's rise with depth against hydrostatics. Still water under P = k ((rho/rho0)^gamma - 1)
// holds dP/dd = g, so rho/rho0 rises by g / (k gamma (rho/rho0)^(gamma - 1)) per metre of depth.
struct DensityProfile {
  double slope = 0.0;        // measured d(rho/rho0)/d(depth), 1/m
  double hydrostatic = 0.0;  // the same by hydrostatics at the measured mean ratio, 1/m
  int rows = 0;              // rows of cells fitted
};

// From the density ratio grid (LiquidNode::read_density_ratio()): the mean over the middle 80 % of
// the columns (x; all of z) of each row of cells, fitted by least squares over the rows whose
// centres lie more than a kernel radius above the floor and below `surface` (m), where the kernel
// is cut off. No rows: slope and hydrostatic 0.
DensityProfile density_profile(const std::vector<float>& density_ratio, const SimulationSetup& setup, double surface);

}  // namespace liquid
