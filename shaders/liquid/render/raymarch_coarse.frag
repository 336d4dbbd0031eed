#version 450
// The raymarch's first pass: one ray per LIQUID_RAYMARCH_COARSE_PIXELS^2 pixels, marched to its
// first crossing of the iso level exactly as the full-resolution pass marches (raymarch_march.glsl);
// writes the distance along the ray, or k_no_hit. The full-resolution pass starts each pixel's march
// just before its coarse neighbours' crossings, and leaves out the liquid where none of them met it.
#extension GL_GOOGLE_include_directive : require
#define DIM 3
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

#include "liquid/render/raymarch_march.glsl"

layout(location = 0) in vec2 v_uv;  // fullscreen.vert's, unused
layout(location = 0) out float out_crossing;

void main() {
  vec2 coarse_ray = floor(gl_FragCoord.xy);
  vec2 pixel = coarse_ray * float(LIQUID_RAYMARCH_COARSE_PIXELS) + 0.5 * float(LIQUID_RAYMARCH_COARSE_PIXELS);
  vec3 origin, dir;
  view_ray(pixel / vec2(r.viewport_width, r.viewport_height), origin, dir);
  vec2 span = intersect_box(origin, 1.0 / dir, vec3(0.0), u.domain);
  vec2 along = liquid_span(origin, dir, span);
  out_crossing = span.x <= span.y && span.y > 0.0 ? march_liquid(origin, dir, along.x, along.y) : k_no_hit;
}
