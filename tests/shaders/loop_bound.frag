#version 450
// Reproducer of lavapipe's per-draw memory (Mesa 22.3; docs/memory.md): a loop whose trip count
// is read from a uniform block, in a shader that reads a second uniform block. Built twice:
// BOUND_FROM_UNIFORM=1 reads the count from the block, 0 from a specialization constant (what the
// liquid's shaders do instead).
layout(std140, set = 0, binding = 0) uniform First {
  vec4 offset;
} a;
layout(std140, set = 0, binding = 1) uniform Second {
  mat4 transform;
  int count;
} b;
layout(constant_id = 0) const int COUNT = 5;

layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_color;

void main() {
  // Over a hundred values before the loop: the driver leaves smaller shaders alone.
  vec4 p = b.transform * vec4(v_uv, 1.0, 1.0);
  vec3 q = normalize(p.xyz / p.w - a.offset.xyz);
  for (int i = 0; i < 6; ++i) q = normalize(abs(q.yzx * 1.3 - q) + vec3(0.1, 0.2, 0.3) * float(i));
  float lo = 0.0, hi = length(q) + dot(q, a.offset.xyz);
#if BOUND_FROM_UNIFORM
  for (int k = 0; k < b.count; ++k) {
#else
  for (int k = 0; k < COUNT; ++k) {
#endif
    float m = 0.5 * (lo + hi);
    if (sin(m * 20.0) > 0.5) hi = m;
    else lo = m;
  }
  out_color = vec4(lo, hi, 0.0, 1.0);
}
