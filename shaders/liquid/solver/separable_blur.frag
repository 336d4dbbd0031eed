#version 450
// One axis of a separable spread over the grid (a full-screen grid pass, grid_fragment.glsl): the
// cell's value becomes sum_j b_j v(c + j e_AXIS) with the splat kernel's taps b_j = w(j, r) =
// (1 - j^2/r^2)^3, |j| <= ceil(r) - 1, and cells beyond a wall read as their mirror images inside.
// Run once per axis (AXIS = 0, 1, 2: compiled variants), it applies the tensor-product kernel
//   W(d) = prod_a b(d_a).
// Two uses:
//   - The separable splat (GHOST_RISE 0): spreads deposit.frag's (sum w u, sum w) into the splat
//     grid, unnormalised, so the density is a sum of kernel weights as the chapter's splat's is.
//   - The separable splat's adjoint potential (GHOST_RISE 1): Phi = W^T P, normalised by the taps'
//     sum, with the hydrostatic rise of the ghost cells beyond a wall gravity points into, as
//     potential.frag gathers it for the point-sprite splat (W is symmetric, and with mirrored taps
//     it stays symmetric at the walls, so the same passes are its own transpose). The rise is linear
//     in the taps, so adding each axis's part in its own pass gives potential.frag's sum.
#ifndef GHOST_RISE
#define GHOST_RISE 0
#endif
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_BLUR_SOURCE) uniform GRID_SAMPLER u_source;

layout(location = 0) out vec4 out_value;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_value = vec4(0.0);
    return;
  }
  int n = grid_cells()[AXIS];
  float inv_r2 = 1.0 / (u.kernel_radius * u.kernel_radius);
  int reach = int(ceil(u.kernel_radius)) - 1;  // the same for every fragment: a uniform trip count
  vec4 total = vec4(0.0);
  float weights = 0.0;
  for (int j = -reach; j <= reach; ++j) {
    float t = 1.0 - float(j * j) * inv_r2;
    float w = t * t * t;
    ivec3 q = c;
    q[AXIS] = mirror_index(c[AXIS] + j, n);
    vec4 value = fetch_grid(u_source, q);
#if GHOST_RISE
    value += wall_ghost_rise_along(AXIS, c[AXIS] + j);
#endif
    total += w * value;
    weights += w;
  }
#if GHOST_RISE
  out_value = total / weights;
#else
  out_value = total;
#endif
}
