#version 450
// 2D view, particles: a small round dot, alpha-blended over the liquid.
layout(push_constant) uniform Particles2dPush {
  vec2 origin;
  float pixels_per_metre;
  float point_size;
  vec2 frame;
  int texture_width;
  float alpha;  // opacity of one point
} pc;

layout(location = 0) out vec4 out_color;

void main() {
  float r = length(gl_PointCoord - 0.5) * 2.0;  // 0 at the centre, 1 at the point's edge
  out_color = vec4(0.93, 0.97, 1.0, pc.alpha * (1.0 - smoothstep(0.6, 1.0, r)));
}
