#version 450
// 2D view, a secondary particle: a soft round dot of its kind's colour, alpha-blended over the liquid.
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 out_color;

void main() {
  float r = length(gl_PointCoord - 0.5) * 2.0;  // 0 at the centre, 1 at the point's edge
  out_color = vec4(v_color.rgb, v_color.a * (1.0 - smoothstep(0.5, 1.0, r)));
}
