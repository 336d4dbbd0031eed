#version 450
// 2D view, the secondary particles (Scene::whitewater) over the liquid: one point per slot, its
// position and kind fetched from the whitewater texture by gl_VertexIndex and mapped into the same
// fitted domain rectangle as view2d.frag; a free slot is put outside the clip volume.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
layout(set = 0, binding = LIQUID_BINDING_PARTICLES2D_POSITIONS) uniform sampler2D u_positions;  // xyz m, w kind

layout(push_constant) uniform Particles2dPushBlock {
  Particles2dPush pc;
};

layout(location = 0) flat out vec4 v_color;  // rgb, a opacity

void main() {
  ivec2 texel = ivec2(gl_VertexIndex % pc.texture_width, gl_VertexIndex / pc.texture_width);
  vec4 p = texelFetch(u_positions, texel, 0);
  int kind = int(p.w);
  vec2 pixel = vec2(pc.origin.x + p.x * pc.pixels_per_metre, pc.origin.y - p.y * pc.pixels_per_metre);
  gl_Position = kind == LIQUID_WHITEWATER_FREE ? vec4(0.0, 0.0, -2.0, 1.0) : vec4(pixel / pc.frame * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = pc.point_size;
  v_color = kind == LIQUID_WHITEWATER_BUBBLE  ? vec4(0.75, 0.9, 1.0, 0.6 * pc.alpha)
            : kind == LIQUID_WHITEWATER_SPRAY ? vec4(0.9, 0.95, 1.0, 0.85 * pc.alpha)
                                              : vec4(1.0, 1.0, 1.0, pc.alpha);
}
