#version 450
// 2D view, particles: a small round dot, alpha-blended over the liquid.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
layout(push_constant) uniform Particles2dPushBlock {
  Particles2dPush pc;
};

layout(location = 0) out vec4 out_color;

void main() {
  float r = length(gl_PointCoord - 0.5) * 2.0;  // 0 at the centre, 1 at the point's edge
  out_color = vec4(0.93, 0.97, 1.0, pc.alpha * (1.0 - smoothstep(0.6, 1.0, r)));
}
