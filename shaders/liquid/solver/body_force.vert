#version 450
// Body force pass: the liquid's pressure force and torque on one dynamic obstacle (the push
// constant's), F = -rho0 sum P n dA over its surface, reduced on the raster pipeline: one point per
// grid cell, additively blended into the obstacle's texel of two 1 x N targets (force, torque);
// cells off the body's surface band are clipped away.
// The surface integral on the grid: with the body's occupancy phi = clamp(1/2 - sdf / h, 0, 1), a
// ramp one cell wide centred on the surface, -sum P n dA = sum_c P grad phi_c h^d (by parts; the
// central differences of phi telescope to the face's area exactly). P is the liquid's at the face
// point of the cell, extrapolated linearly along the normal from one and two cells out: there the
// cells are free liquid, whose pressure at rest is still water's whatever the layer against the
// face holds, so the force depends on the body's pose and the liquid's, not on how it got there
// (docs/physics.md, "Bodies that float").
// BODY_ADJOINT (the scene's "pressure_force": "splat_adjoint"): the force is the reaction of the
// liquid's energy E = sum_c h^d C_c rho0 e(rho_c / rho0) to the body's pose, whose gradient in the
// particles is the liquid's force -grad(W^T P) (potential.frag). The body enters E through its
// kernel coverage C (pressure.frag reads rho_c = splat / C), and dE/dC = -h^d p with p = rho0 (r P - e),
// the pressure of the equation of state, so F = -sum_c h^d p_c dC_c/dX: over a column of cells
// across a face, grad C sums to the face's area, and sum_c P_c grad C_c is the surface integral of
// Phi = W^T P, which still water holds hydrostatic (grad Phi = g) whatever its cells' P do.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#ifndef BODY_ADJOINT
#define BODY_ADJOINT 0
#endif
#include "liquid/common.glsl"
#include "liquid/solver/grid_update.glsl"

layout(push_constant) uniform BodyForcePush {
  int body;  // the obstacle
} pc;

layout(location = 0) flat out vec3 v_force;
layout(location = 1) flat out vec3 v_torque;

// The grid pass's pressure at cell c (m^2/s^2).
float cell_pressure(ivec3 c) { return pressure_at(c, cell_coverage(clamp(c, ivec3(0), grid_cells() - 1))); }

// Trilinear (bilinear in 2D) between cell centres.
float pressure_at_point(vec3 x) {
  vec3 g = x / cell_size() - 0.5;
  ivec3 base = ivec3(floor(g));
  vec3 f = g - vec3(base);
#if DIM == 3
  const int corners = 8;
#else
  const int corners = 4;
  f.z = 0.0;
  base.z = 0;
#endif
  float p = 0.0;
  for (int i = 0; i < corners; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 t = mix(1.0 - f, f, vec3(o));
    p += t.x * t.y * t.z * cell_pressure(base + o);
  }
  return p;
}

#if BODY_ADJOINT
layout(set = 0, binding = LIQUID_BINDING_BODY_CELL_PRESSURE) uniform GRID_SAMPLER u_cell_pressure;

// Body `body`'s factor of the kernel coverage at p (body_coverage()'s, before its clamp).
float coverage_factor(int body, vec3 p) {
  float d = obstacle_distance(body, p) / cell_size();
  return d >= 0.0 ? 1.0 - body_mass_beyond(d) : body_mass_beyond(-d);
}

// The equation of state's pressure p / rho0 = r P - e (m^2/s^2) from the Tait form's P (clamped at
// zero below rest density, where the energy e is zero too): k gamma / (gamma + 1) (r^(gamma + 1) - 1).
float state_pressure(float tait) {
  if (tait <= 0.0) return 0.0;
  float ratio_power = tait / u.stiffness + 1.0;  // r^gamma
  float ratio = pow(ratio_power, 1.0 / u.gamma);
  return u.stiffness * u.gamma / (u.gamma + 1.0) * (ratio_power * ratio - 1.0);
}
#endif

float occupancy(vec3 x) { return clamp(0.5 - obstacle_distance(pc.body, x) / cell_size(), 0.0, 1.0); }

#if DIM == 3
const float k_cell_power = 3.0;
#else
const float k_cell_power = 2.0;  // per metre of depth
#endif

void main() {
  const ivec3 n = grid_cells();
  const int index = gl_VertexIndex;
  const ivec3 c = ivec3(index % n.x, (index / n.x) % n.y, index / (n.x * n.y));
  gl_PointSize = 1.0;
  gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // outside the target: clipped
  v_force = vec3(0.0);
  v_torque = vec3(0.0);
  const float h = cell_size();
  const float cell_measure = pow(h, k_cell_power);
  const vec3 x = cell_center(c);
  const float d = obstacle_distance(pc.body, x);
#if BODY_ADJOINT
  if (abs(d) >= (u.kernel_radius + 1.0) * h) return;  // the coverage changes within r, the differences reach h
  // The other bodies' factors: C is their product with this body's (the walls' do not move).
  float others = 1.0;
  [[unroll]] for (int i = 0; i < obstacle_count(); ++i)
    if (obstacle_dynamic(i) && i != pc.body) others *= coverage_factor(i, x);
  if (others * coverage_factor(pc.body, x) <= k_min_body_coverage) return;  // under the clamp: C does not move
  vec3 grad_coverage = vec3(0.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    vec3 e = vec3(0.0);
    e[a] = h;
    grad_coverage[a] = (coverage_factor(pc.body, x + e) - coverage_factor(pc.body, x - e)) / (2.0 * h);
  }
  if (dot(grad_coverage, grad_coverage) == 0.0) return;
  const float p = state_pressure(fetch_grid(u_cell_pressure, c).r);
  v_force = -u.rest_density * p * cell_coverage(c) * others * grad_coverage * cell_measure;
  v_torque = cross(obstacle_offset(pc.body, x), v_force);
#else
  if (abs(d) >= 1.5 * h) return;  // the ramp is within h/2 of the surface, the differences reach h

  vec3 grad_phi = vec3(0.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    vec3 e = vec3(0.0);
    e[a] = h;
    grad_phi[a] = (occupancy(x + e) - occupancy(x - e)) / (2.0 * h);
  }
  if (dot(grad_phi, grad_phi) == 0.0) return;

  const vec3 normal = obstacle_normal(pc.body, x);
  const vec3 face = x - d * normal;
  const float p_face = max(1.25 * pressure_at_point(face + h * normal) + 0.5 * pressure_at_point(face + 2.0 * h * normal) -
                               0.75 * pressure_at_point(face + 3.0 * h * normal),
                           0.0);
  v_force = u.rest_density * p_face * grad_phi * cell_measure;
  v_torque = cross(face - obstacle_frame(pc.body).center, v_force);
#endif
  gl_Position = vec4(0.0, (float(pc.body) + 0.5) / float(obstacle_count()) * 2.0 - 1.0, 0.0, 1.0);
}
