#version 450
// Empty-space skipping for the raymarch: each texel of this coarse volume holds the largest
// rho / rho0 of one BRICK^3 block of the density grid, plus a one-cell border (trilinear lookups
// at a block's edge read the neighbours). Rendered as a layered full-screen pass, or (ATLAS=1, the
// atlas path of liquid/solver/grid_layout.h) as one full-screen pass over the occupancy atlas reading the
// density atlas.
#ifndef ATLAS
#define ATLAS 0
#endif
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
#include "liquid/grid_atlas.glsl"
layout(location = 0) in vec2 v_uv;
#if !ATLAS
layout(location = 1) flat in int v_layer;
#endif
layout(location = 0) out float out_max_density;

#if ATLAS
layout(set = 0, binding = LIQUID_BINDING_OCCUPANCY_DENSITY) uniform sampler2D u_density;
#else
layout(set = 0, binding = LIQUID_BINDING_OCCUPANCY_DENSITY) uniform sampler3D u_density;
#endif
layout(push_constant) uniform OccupancyPushBlock {
  OccupancyPush pc;
};

void main() {
#if ATLAS
  ivec3 brick = atlas_cell(ivec2(gl_FragCoord.xy), pc.bricks, ivec2(pc.brick_columns, pc.brick_rows));
  if (brick.z >= pc.bricks.z) {  // an unused tile
    out_max_density = 0.0;
    return;
  }
  ivec3 cells = pc.grid_cells;
#else
  ivec3 brick = ivec3(ivec2(gl_FragCoord.xy), v_layer);
  ivec3 cells = textureSize(u_density, 0);
#endif
  ivec3 lo = brick * pc.brick_cells - 1;
  ivec3 hi = lo + pc.brick_cells + 1;
  lo = max(lo, ivec3(0));
  hi = min(hi, cells - 1);
  float m = 0.0;
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
#if ATLAS
        ivec2 texel = atlas_texel(ivec3(x, y, z), cells, ivec2(pc.grid_columns, pc.grid_rows));
#else
        ivec3 texel = ivec3(x, y, z);
#endif
        m = max(m, texelFetch(u_density, texel, 0).r);
      }
  out_max_density = m;
}
