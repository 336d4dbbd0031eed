// The walls' kernel coverage: near a wall the splatted kernel is cut off and the density reads
// low, which would pull liquid into the wall; the solver divides the density by the kernel's share
// inside the domain (shaders/liquid/solver/pressure.glsl). These give the share beyond a wall for a
// cell centre k + 0.5 cells from it, the table the uniform block carries.
#pragma once

#include "liquid/scene.h"

#include <vector>

namespace liquid {

// Fraction of the kernel w = (1 - d^2/r^2)^3's mass that lies more than `distance_cells` beyond a
// plane: its profile across a plane is (1 - z^2/r^2)^(3 + (d - 1)/2), integrated by a midpoint rule
// of `samples` intervals across the kernel's diameter.
double kernel_mass_beyond_wall(int dimension, double radius_cells, double distance_cells, int samples);

// The same share as the scene's own lattice sees it: a lattice of spacing `spacing_cells` whose
// first layer is half a spacing from the wall, summed at a cell centre `distance_cells` from it
// against the lattice continued through the wall (its mirror image), averaged over the lattice's
// offsets along the wall. Uniform liquid then reads exactly its rest density in every wall cell,
// as the automatic rest density makes it read inside.
double lattice_mass_beyond_wall(int dimension, double spacing_cells, double radius_cells, double distance_cells);

// The chapter mode keeps the 16-interval rule it was validated with: it reads uniform liquid 7 %
// dense in the wall cell, a soft layer that holds still water up but kicks liquid off a wall where
// the wall meets a free surface. The splat-adjoint mode takes the lattice's own share and holds
// still water with hydrostatic ghost cells instead (wall_ghost_rise_along in
// shaders/liquid/common.glsl; docs/physics.md, "Start-up next to a wall").
constexpr int k_wall_samples_chapter = 16;

// The table for cells k + 0.5 cells from a wall, k = 0 .. size - 1, for the scene's mode. The
// separable splat needs none (all zeros): it deposits a particle near a wall with its mirror image's
// share folded in and spreads the deposit with mirrored taps, so the walls are already the lattice
// continued through them (shaders/liquid/solver/deposit.vert, separable_blur.frag).
std::vector<float> wall_share_beyond(const Scene& scene, double spacing_cells, int size);

// The table for a dynamic body's surface: the lattice's own share in every mode, so uniform liquid
// beside a body reads its rest density (the chapter's 16-interval rule reads it 7 % dense in the
// nearest cell, a pressure of 40 cm of water at the chapter's k and gamma: docs/physics.md, "Bodies
// that float").
std::vector<float> body_share_beyond(const Scene& scene, double spacing_cells, int size);

}  // namespace liquid
