#version 450
// The tank's frame (tank_frame.glsl), LIQUID_TANK_FRAME_BAR_VERTICES a bar: for each, a screen-space quad
// around the bar's projection, as wide as its radius seen from either side across it and half again,
// plus a pixel, so that it holds every pixel whose ray meets the bar; tank_frame.frag then traces
// the bar exactly. Drawn from gl_VertexIndex alone (no vertex buffer).
#extension GL_GOOGLE_include_directive : require
#define DIM 3
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

#include "liquid/render/raymarch_view.glsl"
#include "liquid/render/tank_frame.glsl"

layout(location = 0) flat out int v_edge;

// Keeps a point in front of the camera: clip w at least this.
const float k_min_w = 1e-4;

vec2 to_pixels(vec4 clip) { return clip.xy / clip.w * 0.5 * vec2(r.viewport_width, r.viewport_height); }

// The bar's radius in pixels at `p` on it, from the two axes across it (`across` and `across2`).
float radius_in_pixels(vec3 p, vec4 clip, vec3 across, vec3 across2, float radius) {
  vec4 c1 = r.view_projection * vec4(p + across * radius, 1.0), c2 = r.view_projection * vec4(p + across2 * radius, 1.0);
  vec2 centre = to_pixels(clip);
  float seen = max(length(to_pixels(vec4(c1.xy, c1.z, max(c1.w, k_min_w))) - centre),
                   length(to_pixels(vec4(c2.xy, c2.z, max(c2.w, k_min_w))) - centre));
  return min(seen, r.viewport_width + r.viewport_height);
}

void main() {
  int edge = gl_VertexIndex / LIQUID_TANK_FRAME_BAR_VERTICES, corner = gl_VertexIndex % LIQUID_TANK_FRAME_BAR_VERTICES;
  v_edge = edge;
  vec3 a, along;
  tank_edge(edge, a, along);
  float radius = tank_frame_radius();
  vec3 axis = normalize(along);
  int axis_index = edge / 4;
  vec3 across = vec3(0.0), across2 = vec3(0.0);
  across[(axis_index + 1) % 3] = 1.0;
  across2[(axis_index + 2) % 3] = 1.0;
  // The bar with its round ends, as a segment, cut to the part in front of the camera.
  vec3 p0 = a - axis * radius, p1 = a + along + axis * radius;
  vec4 c0 = r.view_projection * vec4(p0, 1.0), c1 = r.view_projection * vec4(p1, 1.0);
  if (c0.w < k_min_w && c1.w < k_min_w) {
    gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);  // behind the camera: nothing to draw
    return;
  }
  if (c0.w < k_min_w) {
    float s = (k_min_w - c0.w) / (c1.w - c0.w);
    p0 = mix(p0, p1, s);
    c0 = mix(c0, c1, s);
  } else if (c1.w < k_min_w) {
    float s = (k_min_w - c1.w) / (c0.w - c1.w);
    p1 = mix(p1, p0, s);
    c1 = mix(c1, c0, s);
  }
  vec2 s0 = to_pixels(c0), s1 = to_pixels(c1);
  float half0 = 1.5 * radius_in_pixels(p0, c0, across, across2, radius) + 1.0;
  float half1 = 1.5 * radius_in_pixels(p1, c1, across, across2, radius) + 1.0;
  vec2 d = s1 - s0;
  vec2 forward = length(d) > 1e-3 ? normalize(d) : vec2(1.0, 0.0), side = vec2(-forward.y, forward.x);
  // (0, -) (1, -) (0, +) and (0, +) (1, -) (1, +): which end, which side.
  bool far_end = corner == 1 || corner == 4 || corner == 5;
  float sign_side = corner == 2 || corner == 3 || corner == 5 ? 1.0 : -1.0;
  vec2 pixel = far_end ? s1 + forward * half1 + side * sign_side * half1 : s0 - forward * half0 + side * sign_side * half0;
  gl_Position = vec4(pixel / (0.5 * vec2(r.viewport_width, r.viewport_height)), 0.0, 1.0);
}
