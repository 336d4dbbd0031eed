#version 450
// 2D view, particles on top of the liquid: one point per active particle, its position fetched
// from the particle texture by gl_VertexIndex (no vertex buffer) and mapped into the same fitted
// domain rectangle as view2d.frag.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
layout(set = 0, binding = LIQUID_BINDING_PARTICLES2D_POSITIONS) uniform sampler2D u_positions;  // RGBA32F, xyz m, nearest

layout(push_constant) uniform Particles2dPushBlock {
  Particles2dPush pc;
};

void main() {
  ivec2 texel = ivec2(gl_VertexIndex % pc.texture_width, gl_VertexIndex / pc.texture_width);
  vec2 p = texelFetch(u_positions, texel, 0).xy;
  vec2 pixel = vec2(pc.origin.x + p.x * pc.pixels_per_metre, pc.origin.y - p.y * pc.pixels_per_metre);
  gl_Position = vec4(pixel / pc.frame * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = pc.point_size;
}
