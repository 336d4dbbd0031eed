#version 450
// A secondary particle's sprite: a soft disc, alpha-blended over the view and tested against its
// depth (the liquid's surface, obstacles, the host's geometry), written in the target's encoding.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"

layout(constant_id = LIQUID_WHITEWATER_DRAW_OUTPUT_ID) const int OUTPUT_ENCODING = LIQUID_OUTPUT_DISPLAY;

layout(push_constant) uniform WhitewaterDrawBlock {
  WhitewaterDrawPush pc;
};

layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 out_color;

void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  float r2 = dot(d, d);
  if (r2 > 1.0) discard;
  float alpha = v_color.a * (1.0 - r2 * r2);
  vec3 color = v_color.rgb * (0.88 + 0.12 * (1.0 - r2));  // a little darker at the rim
  if (OUTPUT_ENCODING == LIQUID_OUTPUT_LINEAR)
    color = pow(color, vec3(2.2));
  else if (OUTPUT_ENCODING == LIQUID_OUTPUT_HDR)
    color = pow(color, vec3(2.2)) * pc.exposure;
  out_color = vec4(color, alpha);
}
