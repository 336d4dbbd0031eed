#version 450
// Pressure projection, first pass: each liquid cell's row of the Poisson equation lap p = div u* / dt
// that the Jacobi passes solve, where u* = u + dt (g + f_ext) is the velocity the step would have
// without pressure (u the splat's). The divergence takes face velocities as the means of the two
// cells' (a cell the splat does not reach takes its neighbour's); a wall's face carries none, a
// solid cell's (a static obstacle's or a dynamic body's: projection.glsl) the obstacle's velocity.
// The row's diagonal counts 1 per liquid neighbour and 1/theta per air one (the ghost pressure
// p (1 - 1/theta) that puts p = 0 on the surface: projection.glsl); a wall's or a solid cell's face
// drops out.
// The density correction's row shares the diagonal; its right side is -rate e h^2, e = rho / rho0 - 1
// where no air lies within the kernel's reach of the cell (along the axes, ceil(r) cells away) and no
// solid obstacle either, and only its excess beyond a margin elsewhere: a cell near the surface
// reads the air above it as a deficit that gathering liquid into it would not fill, only draw the
// surface down; beside an obstacle the particles' skin leaves a gap the same way.
// It also takes the first Jacobi iteration (projection_jacobi.frag) from the last step's (p, psi), the
// row being at hand: one pass fewer, whose fixed cost on lavapipe is most of an iteration's.
// Output: target 0 = (h^2 div u* / dt, the diagonal's weight, -rate e h^2, fraction) in liquid cells,
// (0, 0, 0, fraction) in air, where fraction is the cell's liquid fraction (k_solid_cell_fraction in
// a solid cell), which the grid pass reads instead of computing it again at each neighbour.
// Target 1 = the first iterate's (p, psi), 0 in air.
// With dt = 0 (the grid passes of a frame that does not step) only the fractions are needed.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES  // the bodies are solid (projection.glsl)
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/pressure.glsl"

layout(set = 0, binding = LIQUID_BINDING_PRESSURE_SPLAT) uniform GRID_SAMPLER u_splat;
layout(set = 0, binding = LIQUID_BINDING_PROJECTION_PRESSURE) uniform GRID_SAMPLER u_pressure;  // the last step's

#include "liquid/solver/projection.glsl"

layout(location = 0) out vec4 out_system;
layout(location = 1) out vec2 out_first_iterate;

// u* of a cell whose splat is s and where the brushes' acceleration is f.
vec3 provisional_velocity(vec4 s, vec3 f) { return s.rgb / max(s.a, k_fluid_epsilon) + u.dt * (u.gravity + f); }

// The brushes' acceleration f_ext at cell c's centre, and along each axis a at its neighbours' on
// that axis (at [2 a] the lower, [2 a + 1] the upper), in one pass over the brushes: a pass per
// neighbour (external_acceleration()) cost lavapipe more than half of this pass's time, brushes or
// none (docs/physics.md, "A pressure projection").
vec3 brush_accelerations(ivec3 c, out float along[2 * DIM]) {
  vec3 x = cell_center(c), here = vec3(0.0);
  [[unroll]] for (int k = 0; k < 2 * DIM; ++k) along[k] = 0.0;
  for (int i = 0; i < u.brush_count; ++i) {
    Brush b = u.brushes[i];
    here += brush_acceleration(b, x);
    [[unroll]] for (int k = 0; k < 2 * DIM; ++k) {
      vec3 p = x;
      p[k / 2] += (k % 2 == 0 ? -1.0 : 1.0) * cell_size();
      along[k] += brush_acceleration(b, p)[k / 2];
    }
  }
  return here;
}

void main() {
  ivec3 c;
  out_first_iterate = vec2(0.0);
  if (!grid_fragment_cell(c)) {
    out_system = vec4(0.0);
    return;
  }
  vec4 splat = fetch_grid(u_splat, c);
  SolidObstacle nearest = nearest_solid_obstacle(c);
  float fc = liquid_fraction(c, splat, nearest);  // 0 in a solid cell: no row
  if (fc < k_surface_fraction || u.dt <= 0.0) {
    out_system = vec4(0.0, 0.0, 0.0, nearest.distance < 0.0 ? k_solid_cell_fraction : fc);
    return;
  }
  ivec3 n = grid_cells();
  float f_along[2 * DIM];
  vec3 here = provisional_velocity(splat, brush_accelerations(c, f_along));
  float divergence = 0.0, weight = 0.0;
  vec2 neighbours = vec2(0.0);  // the last step's (p, psi) summed as projection_jacobi.frag sums them
  int reach = int(ceil(u.kernel_radius));
  float h = cell_size();
  bool deep = nearest.distance >= float(reach) * h;
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      ivec3 q = c;
      q[a] += side;
      if (q[a] < 0 || q[a] >= n[a]) continue;  // a wall: no flow, no term
      neighbours += fetch_grid(u_pressure, q).rg;
      SolidObstacle solid = nearest_solid_obstacle(q);
      if (solid.distance < 0.0) {  // the obstacle's flow through the face, no term
        vec3 face = cell_center(c);
        face[a] += 0.5 * float(side) * h;
        divergence += float(side) * obstacle_velocity_at(solid.index, face)[a];
        continue;
      }
      vec4 s = fetch_grid(u_splat, q);  // one read for the face's velocity and q's fraction
      float there = s.rgb[a] / max(s.a, k_fluid_epsilon) + u.dt * (u.gravity[a] + f_along[2 * a + (side + 1) / 2]);
      divergence += float(side) * (s.a > k_fluid_epsilon ? 0.5 * (here[a] + there) : here[a]);
      float fq = liquid_fraction(q, s, solid);
      weight += fq >= k_surface_fraction ? 1.0 : 1.0 / surface_distance(fc, fq);
      q[a] = clamp(c[a] + side * reach, 0, n[a] - 1);  // the kernel's reach; a wall is no air
      deep = deep && fq >= k_surface_fraction && liquid_fraction(q) >= k_surface_fraction;
    }
  }
  float error = deep ? fc - 1.0 : max(fc - 1.0 - k_surface_excess_margin, 0.0);
  // h^2 (divergence / h) / dt, and the correction's h^2 (-rate e)
  out_system = vec4(h * divergence / u.dt, weight, -k_density_correction_rate * error * h * h, fc);
  out_first_iterate = (neighbours - out_system.xz) / out_system.y;
}
