// A dynamic obstacle's rigid-body constants, from its shape (spheres and boxes): volume, mass,
// principal moments of inertia and the integrator's added mass. In 2D a shape is its cross-section
// (a disc or a rectangle) and every mass is per metre of depth. Pure CPU code.
#pragma once

#include "liquid/scene.h"

#include <glm/glm.hpp>

namespace liquid {

// m^3 (2D: m^2, the cross-section's area).
double body_volume(const Obstacle& obstacle, int dimension);
// m^2 (2D: m, the perimeter).
double body_surface(const Obstacle& obstacle, int dimension);
// kg: the scene's mass, or density times volume.
double body_mass(const Obstacle& obstacle, int dimension);
// kg m^2 about the centre, along the shape's own axes (2D: only z turns; x and y are set equal to it).
glm::vec3 body_inertia(const Obstacle& obstacle, int dimension);

// The integrator's added mass (kg; docs/physics.md, "Bodies that float"): the liquid the body's
// no-inflow condition can set moving within one step, its own volume's worth plus a shell one cell
// thick, at the liquid's density. With an explicit coupling a body lighter than about half that
// liquid overshoots every step and blows up; the term keeps it stable without changing where it
// comes to rest.
double body_added_mass(const Obstacle& obstacle, int dimension, double liquid_density, double cell_size);

// The same for rotation, as a fraction of the body's smallest principal moment: the added mass at
// the body's circumradius (the shell the no-inflow condition turns with it lies there).
double body_added_inertia_ratio(const Obstacle& obstacle, int dimension, double added_mass);

}  // namespace liquid
