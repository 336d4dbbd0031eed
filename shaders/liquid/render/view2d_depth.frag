#version 450
// 2D view, first pass: each cell's depth below the liquid's surface, in cells, for view2d.frag's
// shading: from the cell's centre up one cell at a time to the first cell under the iso level, the
// crossing interpolated between the two (0 outside the liquid, depth_cells at most). Once per cell
// of the density grid instead of once per liquid pixel of the frame: at 1024x768 a 256² grid has a
// twelfth as many cells as the frame has pixels, and lavapipe runs the march's every trip for
// every lane (docs/lavapipe-performance.md).
// Output: target 0 = depth (cells), sampled bilinearly by view2d.frag.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

layout(set = 0, binding = LIQUID_BINDING_VIEW2D_DENSITY) uniform sampler2D u_density;  // rho / rho0, nearest

layout(push_constant) uniform View2dPushBlock {
  View2dPush pc;
};

layout(location = 0) in vec2 v_uv;  // the full-screen vertex shader's, unused: the cell is gl_FragCoord
layout(location = 0) out float out_depth;

void main() {
  ivec2 c = ivec2(gl_FragCoord.xy);
  int top = grid_cells().y;
  float below = texelFetch(u_density, c, 0).r;
  float depth = below < pc.iso_level ? 0.0 : pc.depth_cells;
  bool found = below < pc.iso_level;
  for (int k = 1; k <= int(pc.depth_cells); ++k) {
    float next = c.y + k >= top ? 0.0 : texelFetch(u_density, c + ivec2(0, k), 0).r;
    if (!found && next < pc.iso_level) {
      depth = float(k - 1) + clamp((below - pc.iso_level) / max(below - next, 1e-4), 0.0, 1.0);
      found = true;
    }
    below = found ? below : next;
  }
  out_depth = depth;
}
