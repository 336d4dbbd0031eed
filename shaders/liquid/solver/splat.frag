#version 450
// Splat pass (section 3), fragment stage: the kernel w(d, r) = (1 - d^2/r^2)^3 evaluated at this
// cell's centre, written as (w u, w) and summed by additive blending: rgb = sum w u, a = sum w.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(location = 0) flat in vec4 v_point;  // xy centre (cells), z 1 - dz^2/r^2, w 1/r^2: no uniform read here
layout(location = 1) flat in vec3 v_velocity;
layout(location = 0) out vec4 out_splat;

void main() {
  vec2 d = gl_FragCoord.xy - v_point.xy;
  float t = max(v_point.z - dot(d, d) * v_point.w, 0.0);
  float w = t * t * t;
  out_splat = vec4(w * v_velocity, w);
}
