#version 450
// Active region, second reduction (liquid/solver/active_region.h): one fragment per band of
// LIQUID_ACTIVE_REGION_BAND_ROWS rows of a slice, at (band, slice z): the rectangle of cells
// (x0, y0, x1, y1), inclusive and within the band, that the step's grid passes compute: every
// marked cell of slices z - m ... z + m and of rows within m of the band, widened by m cells in x
// and y, clamped to the band and the grid, with m = u.active_region_margin_cells
// (active_region_margin_cells() says why it is enough). A band with no marked cell within m gets
// x0 > x1: nothing.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(set = 0, binding = LIQUID_BINDING_ACTIVE_ROWS) uniform sampler2D u_rows;  // (first x, last x) at (y, z)
layout(location = 0) in vec2 v_uv;  // the full-screen triangle's (unused: the fragment's position is the band)
layout(location = 0) out vec4 out_rectangle;

void main() {
  ivec2 band_slice = ivec2(gl_FragCoord.xy);
  int z = band_slice.y;
  ivec3 n = grid_cells();
  int m = u.active_region_margin_cells;
  int band_lo = band_slice.x * LIQUID_ACTIVE_REGION_BAND_ROWS;
  int band_hi = min(band_lo + LIQUID_ACTIVE_REGION_BAND_ROWS, n.y) - 1;
  ivec2 lo = n.xy, hi = ivec2(-1);
  for (int slice = max(z - m, 0); slice <= min(z + m, n.z - 1); ++slice) {
    for (int y = max(band_lo - m, 0); y <= min(band_hi + m, n.y - 1); ++y) {
      vec2 span = texelFetch(u_rows, ivec2(y, slice), 0).xy;
      if (span.x <= span.y) {
        lo = min(lo, ivec2(int(span.x), y));
        hi = max(hi, ivec2(int(span.y), y));
      }
    }
  }
  if (hi.x < 0) {
    out_rectangle = vec4(1.0, 1.0, 0.0, 0.0);  // empty
    return;
  }
  out_rectangle = vec4(max(lo.x - m, 0), max(lo.y - m, band_lo), min(hi.x + m, n.x - 1), min(hi.y + m, band_hi));
}
