#version 450
// Grid pass (section 4): one full-screen pass over the grid (one layer per slice in 3D, or the
// whole atlas on the atlas path, grid_fragment.glsl).
//   rho = density_scale * sum w                        (section 3, normalised to kg/m^3)
//   u   = sum w u / sum w                              (the splatted velocity, kept for FLIP)
//   P   = k ((rho + rho_obstacle) / rho0)^gamma        (section 2.1; obstacles, section 6)
//   u'  = u + dt (-grad P + g + f_ext)                 (eq. 2 and 3, forward Euler, central differences)
// (with the Tait clamp described at pressure_from_density) then the boundary conditions: no flow
// through the walls or into obstacles.
// SPLAT_ADJOINT (the scene's "pressure_force": "splat_adjoint"): the gradient is taken of the
// potential Phi = W^T P that potential.frag smoothed from pressure.frag's P with the splat's own
// kernel, which makes the pressure force the gradient of an energy (docs/physics.md).
// PROJECTION (the scene's "projection_iterations"): the gradient is the pressure projection's p's, and
// the pass also writes the density correction's step -grad psi that moves the particles (projection.glsl).
// Outputs: target 0 = (u', fluid flag), target 1 = rho / rho0 (for rendering and diagnostics),
// PROJECTION: target 2 = (-grad psi (m), 0). The update itself is grid_update.glsl's.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/grid_update.glsl"

layout(location = 0) out vec4 out_velocity;
layout(location = 1) out float out_density;
#if PROJECTION
layout(location = 2) out vec4 out_correction;
#endif

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_velocity = vec4(0.0);
    out_density = 0.0;
#if PROJECTION
    out_correction = vec4(0.0);
#endif
    return;
  }
  vec4 splat = fetch_grid(u_splat, c);
  vec3 correction;
  out_velocity = vec4(grid_update(c, splat, correction), splat.a > k_fluid_epsilon ? 1.0 : 0.0);
#if PROJECTION
  out_correction = vec4(correction, 0.0);
#endif
  out_density = u.density_scale * splat.a / u.rest_density;
}
