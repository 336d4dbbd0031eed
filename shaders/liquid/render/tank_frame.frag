#version 450
// One bar of the tank's frame (tank_frame.glsl), traced exactly for this pixel's ray: the closest
// approach of the ray and the bar's axis, a hit within the bar's radius. Depth-tested (less) against
// the raymarched frame, so a bar shows in front of whatever that pixel shows.
#extension GL_GOOGLE_include_directive : require
#define DIM 3
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

#include "liquid/render/raymarch_view.glsl"
#include "liquid/render/tank_frame.glsl"

layout(location = 0) flat in int v_edge;
layout(location = 0) out vec4 out_color;

void main() {
  vec2 pixel = gl_FragCoord.xy - vec2(r.viewport_x, r.viewport_y);
  vec3 origin, dir;
  view_ray(pixel / vec2(r.viewport_width, r.viewport_height), origin, dir);
  vec3 a, e;
  tank_edge(v_edge, a, e);
  // Closest approach of the ray o + t dir and the segment a + s e, s in [0, 1].
  vec3 w = origin - a;
  float b = dot(dir, e), c = dot(e, e), dd = dot(dir, w), ee = dot(e, w);
  float denom = c - b * b;
  if (abs(denom) < 1e-9) discard;
  float t = (b * ee - c * dd) / denom;
  float s = clamp((ee + t * b) / c, 0.0, 1.0);
  t = dot(a + s * e - origin, dir);
  if (t <= 0.0 || length(origin + t * dir - (a + s * e)) >= tank_frame_radius()) discard;
  gl_FragDepth = clip_depth(origin + dir * t);
  out_color = vec4(display_encoded(tank_frame_color()), 1.0);
}
