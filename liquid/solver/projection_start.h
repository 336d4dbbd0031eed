// The pressure projection's first guess. Its Jacobi iterations start each step from the last step's
// solution, so after the first steps a few of them are enough; but from p = 0 a few iterations
// carry the weight of the liquid only a few cells down, and a pool let go at rest fell onto
// itself and rang (with 4 iterations its volume overshot by 6 %). So the run starts from still
// water's pressure over the initial particles: in each column of cells along gravity, p = |g| times
// the height of the liquid above the cell's centre, that height being the particles' volume
// (count times spacing^d) over the column's cross-section; 0 where no particle lies.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"

#include <vector>

namespace liquid {

// (p, psi) per texel of the projection's pressure image in `layout` (the atlas's unused tiles 0), p in
// m^2/s^2 (the pressure over the density), psi 0. All zero unless gravity lies along one axis.
std::vector<float> hydrostatic_projection_start(const SimulationSetup& setup, const GridLayout& layout);

}  // namespace liquid
