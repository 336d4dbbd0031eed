#version 450
// Splat pass (section 3), fragment stage: the kernel w(d, r) = (1 - d^2/r^2)^3 evaluated at this
// cell's centre, written as (w u, w) and summed by additive blending: rgb = sum w u, a = sum w.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(location = 0) flat in vec4 v_point;  // xy centre (pixels), z 1 - dz^2/r^2, w 1/r^2: no uniform read here
layout(location = 1) flat in vec3 v_velocity;
#if AFFINE
layout(location = 3) flat in vec3 v_affine_x;  // C_p's x and y columns times h (splat.vert)
layout(location = 4) flat in vec3 v_affine_y;
#endif
layout(location = 0) out vec4 out_splat;

void main() {
  vec2 d = gl_FragCoord.xy - v_point.xy;
  float t = max(v_point.z - dot(d, d) * v_point.w, 0.0);
  float w = t * t * t;
#if DIM == 3 && ATLAS
  // A point near its tile's edge also covers the neighbouring tile, another slice: only the tile
  // that holds the point's centre receives it (adding zero elsewhere; cheaper than a discard).
  // Float division: lavapipe has no vector integer division, so an ivec2 one runs lane by lane.
  vec2 cells = vec2(u.grid_cells.xy);
  w = floor(gl_FragCoord.xy / cells) == floor(v_point.xy / cells) ? w : 0.0;
#endif
#if AFFINE
  // The affine transfer: u_p + C_p (x_i - x_p), x_i - x_p in cells here (its z part is in v_velocity).
  out_splat = vec4(w * (v_velocity + d.x * v_affine_x + d.y * v_affine_y), w);
#else
  out_splat = vec4(w * v_velocity, w);
#endif
}
