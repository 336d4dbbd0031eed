#version 450
// Body force pass: the liquid's pressure force and torque on one dynamic obstacle (the push
// constant's), reduced on the raster pipeline: one point per grid cell, additively blended into the
// obstacle's texel of two 1 x N targets (force, torque); cells where the force is zero are clipped.
// The force is the reaction of the liquid's energy E = sum_c h^d C_c rho0 e(rho_c / rho0) to the
// body's pose. The gradient of E in the particles is the liquid's pressure force, -grad(W^T P)
// (potential.frag); the body enters E through its kernel coverage C (pressure.frag reads
// rho_c = splat / C), and dE/dC = -h^d p with p = rho0 (r P - e) the equation of state's pressure,
// so F = sum_c h^d p_c dC_c/dX, and C is the walls' share less the bodies' shares at the cell and at
// its images beyond the walls (liquid_coverage), so dC/dX is the gradient of this body's share.
// Over a column of cells across a face grad C sums to the face's area, and sum_c P_c grad C_c is
// the surface integral of Phi = W^T P, which still water holds
// hydrostatic (grad Phi = g) whatever its single cells' P do (docs/physics.md, "Bodies that float").
// The torque: rotating the body moves its coverage the same way about its centre.
// PROJECTION: the body is solid to the pressure projection (projection.glsl), and the force is the
// projection's pressure on it, with whatever the body's motion asks of the liquid (so no exchange
// pass): summed over the faces between neighbouring cells c and q (the walls' faces included),
// F = sum_f rho0 p_f (S_q - S_c) n h^(d-1), with n the axis from c to q, S the body's share of each
// cell (force_share()) and p_f the mean of the two cells' p / rho0. The cells inside the body have
// no p: there it is continued from the liquid cells nearest along the axes as still water's,
// p_q + g.(x_c - x_q), their mean (solid_pressure()). Where p is hydrostatic the sum is then
// rho0 |g| times the body's volume below the surface: Archimedes. (The cell form above,
// sum_c p_c grad S_c by central differences, is the same sum inside the grid, but it lost the face
// on a wall, half a cell's share: a box on the floor lost half its bottom's push and was pressed
// down.)
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/pressure.glsl"

#ifndef PROJECTION
#define PROJECTION 0
#endif

// The equation of state's P, or the projection's (p / rho0, psi).
layout(set = 0, binding = LIQUID_BINDING_BODY_CELL_PRESSURE) uniform GRID_SAMPLER u_cell_pressure;
#if PROJECTION
layout(set = 0, binding = LIQUID_BINDING_GRID_SPLAT) uniform GRID_SAMPLER u_splat;
#include "liquid/solver/projection.glsl"
#endif

layout(push_constant) uniform BodyForcePush {
  int body;  // the obstacle
} pc;

layout(location = 0) flat out vec3 v_force;
layout(location = 1) flat out vec3 v_torque;

// The equation of state's pressure p / rho0 = r P - e (m^2/s^2) from the Tait form's P (clamped at
// zero below rest density, where the energy e is zero too): k gamma / (gamma + 1) (r^(gamma + 1) - 1).
float state_pressure(float tait) {
  if (tait <= 0.0) return 0.0;
  float ratio_power = tait / u.stiffness + 1.0;  // r^gamma
  float ratio = pow(ratio_power, 1.0 / u.gamma);
  return u.stiffness * u.gamma / (u.gamma + 1.0) * (ratio_power * ratio - 1.0);
}

#if PROJECTION
// p / rho0 (m^2/s^2) at liquid cell q whose nearest solid obstacle is o, or 0 where q is air or
// solid (`liquid` false).
float liquid_pressure(ivec3 q, SolidObstacle o, out bool liquid) {
  liquid = o.distance >= 0.0 && liquid_fraction(q, fetch_grid(u_splat, q), o) >= k_surface_fraction;
  return liquid ? fetch_grid(u_cell_pressure, q).r : 0.0;
}

// p / rho0 at solid cell c, continued from the nearest liquid cell along each axis (within the
// kernel's reach plus one: the share changes only across faces within a cell and a half of the
// surface, so the cells that need p find liquid within two) as still water's pressure, the
// candidates' mean; 0 where none is found (above the surface). A cell of air between stops the
// search.
float solid_pressure(ivec3 c) {
  const ivec3 n = grid_cells();
  const int reach = int(ceil(u.kernel_radius)) + 1;
  float sum = 0.0, count = 0.0;
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      for (int k = 1; k <= reach; ++k) {
        ivec3 q = c;
        q[a] += side * k;
        if (q[a] < 0 || q[a] >= n[a]) break;
        SolidObstacle o = nearest_solid_obstacle(q);
        if (o.distance < 0.0) continue;  // still inside
        bool liquid;
        float p = liquid_pressure(q, o, liquid);
        if (liquid) {
          sum += p + dot(u.gravity, cell_center(c) - cell_center(q));
          count += 1.0;
        }
        break;
      }
    }
  }
  return count > 0.0 ? max(sum / count, 0.0) : 0.0;
}

// The pressure (p / rho0, m^2/s^2) that acts on the body's coverage at cell c.
float cell_pressure(ivec3 c) {
  SolidObstacle o = nearest_solid_obstacle(c);
  if (o.distance < 0.0) return solid_pressure(c);
  bool liquid;
  return liquid_pressure(c, o, liquid);
}

// The body's share of the cell (a cube one cell wide) centred at p: the projection's force needs the
// volume it takes from the liquid, not the kernel's view of it. A box's is the product of its slabs'
// overlaps with the cell along its own axes (exact while it is aligned with the grid); a sphere's
// or a mesh's the plane's, 1/2 - d/h clamped. The kernel's share, smoothed over r cells, counts
// some of a box's bottom above the surface where its draft is within r cells (docs/physics.md,
// "Bodies under the projection").
float force_share(vec3 p) {
  float h = cell_size();
  if (obstacle_kind(pc.body) != LIQUID_OBSTACLE_BOX) return clamp(0.5 - obstacle_distance(pc.body, p) / h, 0.0, 1.0);
  vec3 local = quat_rotate_inverse(obstacle_frame(pc.body).orientation, obstacle_offset(pc.body, p)) / h;
  vec3 e = u.obstacles[pc.body].box_half_extent / h;
  float share = 1.0;
  [[unroll]] for (int a = 0; a < DIM; ++a) share *= clamp(min(local[a] + 0.5, e[a]) - max(local[a] - 0.5, -e[a]), 0.0, 1.0);
  return share;
}
const float k_force_share_reach_cells = 0.5;  // how far past the surface force_share changes
#else
float cell_pressure(ivec3 c) { return state_pressure(fetch_grid(u_cell_pressure, c).r); }
float force_share(vec3 p) { return body_share_at(pc.body, p); }
#define k_force_share_reach_cells u.kernel_radius
#endif

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
  const vec3 x = cell_center(c);
  // The share changes within its reach of the surface, and the differences reach a cell further.
  if (abs(obstacle_distance(pc.body, x)) >= (k_force_share_reach_cells + 1.0) * h) return;
#if PROJECTION
  // The faces on c's upper side along each axis, and on its lower side at a wall.
  const float s_c = force_share(x);
  const float p_c = cell_pressure(c);
  const float area = u.rest_density * pow(h, k_cell_power - 1.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      ivec3 q = c;
      q[a] += side;
      const bool wall = q[a] < 0 || q[a] >= n[a];
      if (side < 0 && !wall) continue;  // that face is q's upper one
      vec3 face = x;
      face[a] += 0.5 * float(side) * h;
      // Beyond a wall no cell holds the body: its share is 0 and p is continued as still water's.
      const float s_q = wall ? 0.0 : force_share(cell_center(q));
      if (s_q == s_c) continue;
      const float p_f = wall ? p_c + 0.5 * float(side) * h * u.gravity[a] : 0.5 * (p_c + cell_pressure(q));
      vec3 f = vec3(0.0);
      f[a] = float(side) * area * p_f * (s_q - s_c);
      v_force += f;
      v_torque += cross(obstacle_offset(pc.body, face), f);
    }
  }
#else
  // Under the clamp C does not move.
  if (liquid_coverage(c) <= k_min_body_coverage) return;
  // C = the walls' share - the bodies' shares at x and at its images (liquid_coverage), so
  // dC/dX = the gradient of this body's share at each image q, and a turn about the centre moves
  // it by (q - X) x that gradient.
  const float p = cell_pressure(c);
  if (p == 0.0) return;
  const float weight = u.rest_density * p * pow(h, k_cell_power);
  for (int k = 0; k < body_image_count(); ++k) {
    const vec3 q = body_image(x, k);
    vec3 grad_share = vec3(0.0);
    [[unroll]] for (int a = 0; a < DIM; ++a) {
      vec3 e = vec3(0.0);
      e[a] = h;
      grad_share[a] = (force_share(q + e) - force_share(q - e)) / (2.0 * h);
    }
    v_force += weight * grad_share;
    v_torque += cross(obstacle_offset(pc.body, q), weight * grad_share);
  }
#endif
  if (dot(v_force, v_force) == 0.0 && dot(v_torque, v_torque) == 0.0) return;
  gl_Position = vec4(0.0, (float(pc.body) + 0.5) / float(obstacle_count()) * 2.0 - 1.0, 0.0, 1.0);
}
