// A dynamic obstacle's rigid-body constants, from its shape (spheres, boxes and closed triangle
// meshes): volume, mass, principal moments of inertia and the integrator's added mass. In 2D a
// shape is its cross-section (a disc or a rectangle; meshes are dynamic in 3D only) and every mass
// is per metre of depth. Pure CPU code.
#pragma once

#include "liquid/scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace liquid {

// A closed triangle mesh's mass properties at unit density, exact for the polyhedron (the
// divergence theorem over its triangles; Eberly, "Polyhedral Mass Properties (Revisited)"), in the
// mesh's own frame with its scale applied (not its rotation).
struct MeshMass {
  double volume = 0.0;                 // m^3
  glm::dvec3 centroid{0.0};            // m, the centre of mass
  glm::dmat3 inertia{0.0};             // m^5 (kg m^2 per kg/m^3), about the centroid
};
MeshMass mesh_mass_properties(const TriangleMesh& mesh);

// The principal axes of a symmetric inertia tensor: its eigenvalues (`moments`) and the rotation
// whose columns are the axes (`axes`, det +1), so inertia = R diag(moments) R^T (Jacobi's method).
struct PrincipalAxes {
  glm::dvec3 moments{0.0};
  glm::dquat axes{1.0, 0.0, 0.0, 0.0};
};
PrincipalAxes principal_axes(const glm::dmat3& inertia);

// A dynamic mesh obstacle re-expressed about its centre of mass and principal axes, as a rigid body
// integrates it: the vertices moved and turned into that frame, `center` moved to the centre of
// mass and `rotation` (and the mesh's) turned so that the mesh stays where it was. Other obstacles
// are returned unchanged.
Obstacle mesh_body_in_principal_frame(const Obstacle& obstacle);

// m^3 (2D: m^2, the cross-section's area).
double body_volume(const Obstacle& obstacle, int dimension);
// m^2 (2D: m, the perimeter).
double body_surface(const Obstacle& obstacle, int dimension);
// kg: the scene's mass, or density times volume.
double body_mass(const Obstacle& obstacle, int dimension);
// kg m^2 about the centre, along the shape's own axes (2D: only z turns; x and y are set equal to it).
// A mesh's: the diagonal of its inertia tensor about its centre of mass, its principal moments once
// it is in its principal frame (mesh_body_in_principal_frame).
glm::vec3 body_inertia(const Obstacle& obstacle, int dimension);

// The integrator's added mass (kg; docs/physics.md, "Bodies that float"): the liquid the body's
// no-inflow condition can set moving within one step, its own volume's worth plus a shell one cell
// thick, at the liquid's density. With an explicit coupling a body lighter than about half that
// liquid overshoots every step and blows up; the term keeps it stable without changing where it
// comes to rest.
double body_added_mass(const Obstacle& obstacle, int dimension, double liquid_density, double cell_size);

// A dynamic mesh's distance texture (liquid/solver/body_shapes.h): half the side (m) of the cube
// about the body's centre of mass that its channel spans, its mesh's farthest vertex plus the kernel
// radius and three cells (body_force.vert reads the distance within r + 1 cells of the surface and
// differences it a cell either side).
float body_shape_half_size(const Obstacle& obstacle, float kernel_radius_cells, float cell_size);

// The same for rotation, as a fraction of the body's smallest principal moment: the added mass at
// the body's circumradius (the shell the no-inflow condition turns with it lies there).
double body_added_inertia_ratio(const Obstacle& obstacle, int dimension, double added_mass);

// A mesh's half extents about its own origin (a dynamic mesh's: its centre of mass, along its
// principal axes): its vertices' farthest reach along each axis, scaled.
glm::vec3 mesh_half_extent(const TriangleMesh& mesh);

// Half the body's extent along each world axis at its orientation: the box the wall contact keeps
// inside the domain (world_half_extent() in shaders/liquid/solver/body.frag). A sphere's radius, a
// box's half extents turned, a dynamic mesh's mesh_half_extent() turned.
glm::vec3 body_wall_half_extent(const Obstacle& obstacle);

}  // namespace liquid
