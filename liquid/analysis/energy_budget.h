// Where a step's mechanical energy goes, term by term of the particle pass's update (section 5):
//   v' = v + [I(u') - I(u)] + r [I(u) - v]        then the walls and obstacles,
//   x' = x + dt I(u'(x_mid))                       (RK2 through the grid)
// with I the interpolation to the particle (the chapter's, or under the affine transfer the
// particle pass's fit of a linear field) and u, u' the splatted and updated grid velocities, read
// back after the step. The kinetic energy's change splits into the work of the grid's increment
// (gravity's part and the rest: pressure and the grid's wall and obstacle conditions), the PIC
// share's pull towards the grid, and the particle pass's walls and obstacles; the gravitational
// potential's change is set against gravity's work on the velocities, a mismatch that only the
// advection makes (positions not moving with the velocities). Pure CPU code on what a node reads
// back, used by liquid_validate's budget case; docs/physics.md has its table.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

// Joules over the steps added up; positive: gained.
struct EnergyBudget {
  double kinetic = 0.0;            // the particles' kinetic energy's change
  double potential = 0.0;          // their gravitational potential energy's change
  double gravity_work = 0.0;       // of the grid increment's dt g part on the velocities
  double pressure_and_grid_walls = 0.0;  // of the rest of the grid increment
  double pic = 0.0;                // of the PIC share r [I(u) - v]
  double particle_walls = 0.0;     // of the particle pass's walls and obstacles (what is left)
  // gravity_work + potential: zero when positions move with the velocities; the advection's share.
  double advection() const { return gravity_work + potential; }
  void add(const EnergyBudget& other);
};

// One step's budget: the particles before and after it (the same order), the step's splat
// (sum w u, sum w) and updated grid velocity (u', fluid flag) as the node reads them back, and the
// blend r of that step; `transfer` says how the particle pass read the grids (Transfer::Affine: the
// fit of grid_sample.glsl's fit_grid_affine(), its bilinear read where too few cells hold liquid).
EnergyBudget step_energy_budget(const SimulationSetup& setup, double pic_step, const ParticleSnapshot& before,
                                const ParticleSnapshot& after, const std::vector<glm::vec4>& splat,
                                const std::vector<glm::vec4>& grid_velocity, Transfer transfer = Transfer::PicFlip);

}  // namespace liquid
