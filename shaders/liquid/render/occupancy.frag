#version 450
// Empty-space skipping for the raymarch: each texel of this coarse volume holds the largest
// rho / rho0 of one BRICK^3 block of the density grid, plus a one-cell border (trilinear lookups
// at a block's edge read the neighbours). Rendered as a layered full-screen pass.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
layout(location = 0) in vec2 v_uv;
layout(location = 1) flat in int v_layer;
layout(location = 0) out float out_max_density;

layout(set = 0, binding = LIQUID_BINDING_OCCUPANCY_DENSITY) uniform sampler3D u_density;
layout(push_constant) uniform OccupancyPushBlock {
  OccupancyPush pc;
};

void main() {
  ivec3 cells = textureSize(u_density, 0);
  ivec3 lo = ivec3(ivec2(gl_FragCoord.xy), v_layer) * pc.brick_cells - 1;
  ivec3 hi = lo + pc.brick_cells + 1;
  lo = max(lo, ivec3(0));
  hi = min(hi, cells - 1);
  float m = 0.0;
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) m = max(m, texelFetch(u_density, ivec3(x, y, z), 0).r);
  out_max_density = m;
}
