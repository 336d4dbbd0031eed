#version 450
// Active region, first reduction (liquid/solver/active_region.h): one fragment per row (y, z) of
// the grid, which finds the first and last x whose mark (the weight in alpha: the 3D deposit's
// lower grid, or the point-sprite splat) is non-zero. Output (first x, last x), or (n, -1) for a row
// with none. A row is one fragment's loop of grid_cells().x reads: about one read per cell, against
// the several of each pass the region then trims.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(set = 0, binding = LIQUID_BINDING_ACTIVE_MARKS) uniform GRID_SAMPLER u_marks;
layout(location = 0) in vec2 v_uv;  // the full-screen triangle's (unused: the fragment's position is the row)
layout(location = 0) out vec2 out_span;

void main() {
  ivec2 row = ivec2(gl_FragCoord.xy);  // (y, z)
  int n = grid_cells().x;
  int first = n, last = -1;
  for (int x = 0; x < n; ++x) {
    if (fetch_grid(u_marks, ivec3(x, row.x, row.y)).a > 0.0) {
      first = min(first, x);
      last = x;
    }
  }
  out_span = vec2(first, last);
}
