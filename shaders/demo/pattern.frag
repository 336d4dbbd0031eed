#version 450
// Test pattern with hard, aliased edges (no filtering): a rotated square, a disc and thin lines.
// The FXAA golden test draws it and checks that FXAA smooths its edges.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_color;

void main() {
  vec2 p = v_uv * 2.0 - 1.0;
  vec3 color = vec3(0.1, 0.12, 0.2);
  float a = 0.35;
  mat2 rot = mat2(cos(a), sin(a), -sin(a), cos(a));
  vec2 q = rot * (p - vec2(-0.35, 0.0));
  if (max(abs(q.x), abs(q.y)) < 0.4) color = vec3(0.95, 0.8, 0.2);
  if (length(p - vec2(0.45, 0.2)) < 0.35) color = vec3(0.2, 0.6, 0.95);
  if (abs(p.y - 0.7 * p.x - 0.55) < 0.02) color = vec3(1.0);
  out_color = vec4(color, 1.0);
}
