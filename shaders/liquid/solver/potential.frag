#version 450
// Splat-adjoint pressure, second pass: Phi = W^T P, the cells' pressure smoothed with the splat's
// own kernel w(d, r) = (1 - d^2/r^2)^3 over cell offsets and normalised by the kernel's sum.
// Why: the internal energy is E = sum_c V e(rho_c) with rho_c = sum_p m w(x_c - x_p), so the force
// on a particle is -dE/dx_p = -sum_c V P_c grad w: the gradient of P gathered with the kernel that
// splatted it. Taking grid.frag's central differences of Phi instead of P gives that force (up to
// the interpolation to the particle), so it does no work around a closed path; the chapter's
// gradient of P does, and that work is what made resting water gain energy (docs/physics.md).
// Beyond a wall the cells are the mirror images of those inside (the particles' mirror images,
// which the coverage correction stands for in the density), plus still water's hydrostatic rise
// toward a wall gravity points into (wall_ghost_rise_along, common.glsl).
// Output: target 0 = Phi (m^2/s^2).
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_POTENTIAL_PRESSURE) uniform GRID_SAMPLER u_pressure;

layout(location = 0) out float out_potential;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_potential = 0.0;
    return;
  }
  ivec3 n = grid_cells();
  float r = u.kernel_radius;
  float inv_r2 = 1.0 / (r * r);
  int reach = int(ceil(r)) - 1;  // the largest whole offset below r
  float total = 0.0, weights = 0.0;
#if DIM == 3
  for (int dz = -reach; dz <= reach; ++dz) {
    int z = mirror_index(c.z + dz, n.z);
    float rise_z = wall_ghost_rise_along(2, c.z + dz);
#else
  {
    const int dz = 0, z = 0;
    const float rise_z = 0.0;
#endif
    for (int dy = -reach; dy <= reach; ++dy) {
      int y = mirror_index(c.y + dy, n.y);
      float rise_yz = rise_z + wall_ghost_rise_along(1, c.y + dy);
      // Loop bounds are the same for every fragment (a uniform trip count on lavapipe).
      int span = int(floor(sqrt(max(r * r - float(dy * dy + dz * dz), 0.0))));
      for (int dx = -span; dx <= span; ++dx) {
        float t = max(1.0 - float(dx * dx + dy * dy + dz * dz) * inv_r2, 0.0);
        float w = t * t * t;
        weights += w;
        float mirrored = fetch_grid(u_pressure, ivec3(mirror_index(c.x + dx, n.x), y, z)).r;
        total += w * (mirrored + rise_yz + wall_ghost_rise_along(0, c.x + dx));
      }
    }
  }
  out_potential = total / weights;
}
