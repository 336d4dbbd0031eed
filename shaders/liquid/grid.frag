#version 450
// Grid pass (section 4): one full-screen pass over the grid (one layer per slice in 3D).
//   rho = density_scale * sum w                        (section 3, normalised to kg/m^3)
//   u   = sum w u / sum w                              (the splatted velocity, kept for FLIP)
//   P   = k ((rho + rho_obstacle) / rho0)^gamma        (section 2.1; obstacles, section 6)
//   u'  = u + dt (-grad P + g + f_ext)                 (eq. 2 and 3, forward Euler, central differences)
// (with the Tait clamp described at pressure_at) then the boundary conditions: no flow through the walls or into obstacles.
// Outputs: target 0 = (u', fluid flag), target 1 = rho / rho0 (for rendering and diagnostics).
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(set = 0, binding = 1) uniform GRID_SAMPLER u_splat;

layout(location = 0) in vec2 v_uv;
#if DIM == 3
layout(location = 1) flat in int v_layer;
#endif
layout(location = 0) out vec4 out_velocity;
layout(location = 1) out float out_density;

const float k_fluid_epsilon = 1e-6;

// Fraction of the kernel's mass beyond a wall `a` cells from a cell centre. Cell centres sit
// k + 0.5 cells from a wall, so the CPU tabulates the eight values k = 0..7 (r is at most 8 cells)
// once per step (liquid/uniforms.cpp) instead of integrating here for every neighbour.
float kernel_mass_beyond(float a) {
  int k = int(a);
  if (k >= 8 || a >= u.kernel.x) return 0.0;
  return u.wall_kernel_beyond[k / 4][k % 4];
}

// Near a wall the kernel is cut off and the splatted density reads low, which would pull liquid
// against the wall; dividing by the kernel's share inside the domain removes that bias.
float wall_coverage(ivec3 c) {
  vec3 to_low = vec3(c) + 0.5, to_high = vec3(grid_cells() - c) - 0.5;
  float coverage = (1.0 - kernel_mass_beyond(to_low.x)) * (1.0 - kernel_mass_beyond(to_high.x)) *
                   (1.0 - kernel_mass_beyond(to_low.y)) * (1.0 - kernel_mass_beyond(to_high.y));
#if DIM == 3
  coverage *= (1.0 - kernel_mass_beyond(to_low.z)) * (1.0 - kernel_mass_beyond(to_high.z));
#endif
  return coverage;
}

// Which of the position-dependent terms of total_density() can be non-zero around a cell, decided
// once per cell instead of for each of its 2d neighbours: away from the walls and obstacles (most
// of the grid) the wall correction is exactly 1 and the obstacle density exactly 0.
struct Surroundings {
  bool near_wall;
  bool near_obstacle;
};

Surroundings surroundings(ivec3 c) {
  Surroundings s;
  // A neighbour is one cell closer to a wall; the correction is 1 from r cells on (cell centres).
  vec3 to_wall = min(vec3(c), vec3(grid_cells() - 1 - c)) + 0.5;
#if DIM == 2
  to_wall.z = 1e9;
#endif
  s.near_wall = any(lessThan(to_wall, vec3(u.kernel.x + 1.0)));
  // Spheres and boxes have exact distances (1-Lipschitz): a neighbour, h away, is at most h closer.
  // The metaballs' first-order estimate is not, so they always count as near.
  s.near_obstacle = false;
  vec3 p = cell_center(c);
  for (int i = 0; i < u.counts.w; ++i)
    if (int(u.obstacles[i].center_kind.w) == OBSTACLE_METABALLS ||
        obstacle_distance(i, p) < u.kernel.w + 1.5 * cell_size())
      s.near_obstacle = true;
  return s;
}

// Total density (kg/m^3) seen by the pressure at cell c: liquid plus obstacle or ground.
float total_density(ivec3 c, Surroundings s) {
  c = clamp(c, ivec3(0), grid_cells() - 1);
  float rho = u.pressure.w * fetch_grid(u_splat, c).a;
  if (s.near_wall) rho /= wall_coverage(c);
  vec3 p = cell_center(c);
  if (s.near_obstacle) rho += obstacle_density(p);
  if (u.counts2.w == 1) rho += u.pressure.z * ground_height(p.xy) / u.shallow.x;
  return rho;
}

// Liquid (default): Becker and Teschner's Tait form, which the chapter cites, clamped at zero:
// P = max(k ((rho/rho0)^gamma - 1), 0). Its gradient equals the printed P = k (rho/rho0)^gamma's
// wherever rho > rho0, but below rest density (the free surface, empty cells) it exerts no pull
// and no push, so the surface stays sharp instead of boiling off. Shallow water and the 'chapter'
// option use the printed form (with gamma = 1 it is the SWE's P = g (h + b)).
float pressure_at(ivec3 c, Surroundings s) {
  float ratio_pow = pow(max(total_density(c, s) / u.pressure.z, 0.0), u.pressure.y);
  return u.counts2.w == 0 ? u.pressure.x * max(ratio_pow - 1.0, 0.0) : u.pressure.x * ratio_pow;
}

void main() {
  ivec3 c = ivec3(gl_FragCoord.xy, 0);
#if DIM == 3
  c.z = v_layer;
#endif
  ivec3 n = grid_cells();
  float h = cell_size();
  float dt = u.gravity_dt.w;
  vec4 splat = fetch_grid(u_splat, c);
  bool fluid = splat.a > k_fluid_epsilon;
  vec3 velocity = fluid ? splat.rgb / splat.a : vec3(0.0);

  // Eq. 3: central differences of the pressure (one-sided at the walls via the clamped fetch).
  Surroundings around = surroundings(c);
  vec3 grad_p;
  grad_p.x = pressure_at(c + ivec3(1, 0, 0), around) - pressure_at(c - ivec3(1, 0, 0), around);
  grad_p.y = pressure_at(c + ivec3(0, 1, 0), around) - pressure_at(c - ivec3(0, 1, 0), around);
  grad_p.z = 0.0;
#if DIM == 3
  grad_p.z = pressure_at(c + ivec3(0, 0, 1), around) - pressure_at(c - ivec3(0, 0, 1), around);
#endif
  grad_p /= 2.0 * h;

  vec3 p = cell_center(c);
  vec3 acceleration = -grad_p + u.gravity_dt.xyz + external_acceleration(p);
  velocity += dt * acceleration;

  // Obstacles: inside, the liquid moves with the obstacle; near the surface, no relative
  // velocity into it.
  for (int i = 0; i < u.counts.w; ++i) {
    float d = obstacle_distance(i, p);
    if (d > h) continue;
    vec3 v_obstacle = u.obstacles[i].velocity.xyz;
    if (d < 0.0) {
      velocity = v_obstacle;
    } else {
      vec3 normal = obstacle_normal(i, p);
      float into = dot(velocity - v_obstacle, normal);
      if (into < 0.0) velocity -= into * normal;
    }
  }

  // Section 4's wall condition: in a cell next to a wall, the velocity component normal to that
  // wall is zero.
  if ((c.x == 0 && velocity.x < 0.0) || (c.x == n.x - 1 && velocity.x > 0.0)) velocity.x = 0.0;
  if ((c.y == 0 && velocity.y < 0.0) || (c.y == n.y - 1 && velocity.y > 0.0)) velocity.y = 0.0;
#if DIM == 3
  if ((c.z == 0 && velocity.z < 0.0) || (c.z == n.z - 1 && velocity.z > 0.0)) velocity.z = 0.0;
#else
  velocity.z = 0.0;
#endif

  out_velocity = vec4(velocity, fluid ? 1.0 : 0.0);
  out_density = u.pressure.w * splat.a / u.pressure.z;
}
