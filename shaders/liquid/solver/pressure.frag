#version 450
// Splat-adjoint pressure, first pass: the pressure P of every cell (section 2.1's Tait form with the
// walls' coverage, plus the obstacles' and the ground's artificial density, section 6), exactly as
// grid.frag computes it for its neighbours, with the dynamic bodies' kernel coverage (liquid_coverage).
// potential.frag then smooths it.
// Output: target 0 = P (m^2/s^2).
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/pressure.glsl"

layout(set = 0, binding = LIQUID_BINDING_PRESSURE_SPLAT) uniform GRID_SAMPLER u_splat;

layout(location = 0) out float out_pressure;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_pressure = 0.0;
    return;
  }
  float rho = u.density_scale * fetch_grid(u_splat, c).a / liquid_coverage(c);
  rho += obstacle_density_at_cell(c);
  if (shallow_water()) rho += u.rest_density * ground_height(cell_center(c).xy) / u.rest_depth;
  out_pressure = pressure_from_density(rho);
}
