#version 450
// Pressure projection, first pass: the divergence of the velocity the step would have without
// pressure, u* = u + dt (g + f_ext), where u is the splat's. Face velocities are the means of the two
// cells' (a cell the splat does not reach takes its neighbour's); a wall's face carries none.
// Output: target 0 = div u* (1/s), in liquid cells; 0 in air.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/pressure.glsl"

layout(set = 0, binding = LIQUID_BINDING_PRESSURE_SPLAT) uniform GRID_SAMPLER u_splat;

#include "liquid/solver/projection.glsl"

layout(location = 0) out float out_divergence;

// u* at cell c, and whether the splat reaches it.
bool provisional_velocity(ivec3 c, out vec3 velocity) {
  vec4 s = fetch_grid(u_splat, c);
  velocity = s.rgb / max(s.a, k_fluid_epsilon) + u.dt * (u.gravity + external_acceleration(cell_center(c)));
  return s.a > k_fluid_epsilon;
}

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c) || liquid_fraction(c) < k_surface_fraction) {
    out_divergence = 0.0;
    return;
  }
  ivec3 n = grid_cells();
  vec3 here;
  provisional_velocity(c, here);
  float divergence = 0.0;
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      ivec3 q = c;
      q[a] += side;
      float face = 0.0;  // a wall's
      if (q[a] >= 0 && q[a] < n[a]) {
        vec3 there;
        face = provisional_velocity(q, there) ? 0.5 * (here[a] + there[a]) : here[a];
      }
      divergence += float(side) * face;
    }
  }
  out_divergence = divergence / cell_size();
}
