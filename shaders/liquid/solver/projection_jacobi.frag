#version 450
// Pressure projection, one Jacobi iteration of the Poisson equation lap p = div u* / dt (p in
// m^2/s^2, the pressure over the density), whose gradient makes u* divergence-free: the grid pass
// then takes u' = u* - dt grad p. Each liquid cell's row comes from the divergence pass: walls drop
// out (no flow through them, Neumann), air neighbours enter the diagonal only (p = 0 on the surface,
// projection.glsl), so their p, which every iteration writes as 0, adds nothing to the sum. The
// first iteration starts from the last step's p (where a cell has just turned to air, its old p
// enters that one iteration's sum; the iterations after it read 0 there).
// The density correction's psi (m^2, projection.glsl) is solved beside p, by the same rows' weights.
// The row pass (projection_divergence.frag) takes the first iteration, these passes the others.
// Output: target 0 = (p (m^2/s^2), psi (m^2)); 0 in air.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_PROJECTION_PRESSURE) uniform GRID_SAMPLER u_pressure;
layout(set = 0, binding = LIQUID_BINDING_PROJECTION_SYSTEM) uniform GRID_SAMPLER u_system;

layout(location = 0) out vec2 out_pressure;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_pressure = vec2(0.0);
    return;
  }
  vec4 row = fetch_grid(u_system, c);  // (h^2 div u* / dt, the diagonal's weight, -rate e h^2)
  if (row.y <= 0.0) {  // air
    out_pressure = vec2(0.0);
    return;
  }
  ivec3 n = grid_cells();
  vec2 neighbours = vec2(0.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      ivec3 q = c;
      q[a] += side;
      if (q[a] >= 0 && q[a] < n[a]) neighbours += fetch_grid(u_pressure, q).rg;
    }
  }
  out_pressure = (neighbours - row.xz) / row.y;
}
