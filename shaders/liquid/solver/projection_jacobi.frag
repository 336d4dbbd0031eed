#version 450
// Pressure projection, one Jacobi iteration of the Poisson equation lap p = div u* / dt (p in
// m^2/s^2, the pressure over the density), whose gradient makes u* divergence-free: the grid pass
// then takes u' = u* - dt grad p. Walls: no flow through them (their faces drop out, Neumann). Air:
// p = 0 at the surface (projection.glsl). The first iteration starts from the last step's p.
// Output: target 0 = p (m^2/s^2).
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/pressure.glsl"

layout(set = 0, binding = LIQUID_BINDING_PRESSURE_SPLAT) uniform GRID_SAMPLER u_splat;
layout(set = 0, binding = LIQUID_BINDING_PROJECTION_PRESSURE) uniform GRID_SAMPLER u_pressure;
layout(set = 0, binding = LIQUID_BINDING_PROJECTION_DIVERGENCE) uniform GRID_SAMPLER u_divergence;

#include "liquid/solver/projection.glsl"

layout(location = 0) out float out_pressure;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_pressure = 0.0;
    return;
  }
  float fc = liquid_fraction(c);
  if (fc < k_surface_fraction) {
    out_pressure = 0.0;
    return;
  }
  ivec3 n = grid_cells();
  float neighbours = 0.0, weight = 0.0;
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      ivec3 q = c;
      q[a] += side;
      if (q[a] < 0 || q[a] >= n[a]) continue;  // a wall
      float fq = liquid_fraction(q);
      if (fq >= k_surface_fraction) {
        neighbours += fetch_grid(u_pressure, q).r;
        weight += 1.0;
      } else {
        weight += 1.0 / surface_distance(fc, fq);  // the ghost pressure p (1 - 1/theta)
      }
    }
  }
  float h = cell_size();
  float rhs = h * h * fetch_grid(u_divergence, c).r / u.dt;
  out_pressure = (neighbours - rhs) / weight;
}
