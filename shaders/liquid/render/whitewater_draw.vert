#version 450
// The secondary particles over the 3D view: one point sprite per slot, its position and kind
// fetched from the whitewater texture by gl_VertexIndex (no vertex buffer). A free slot is put
// outside the clip volume. A sprite is `radius` across in the world; a bubble is drawn
// `bubble_lift` toward the camera, so those just under the surface show through it.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"

layout(set = 0, binding = LIQUID_BINDING_WHITEWATER_DRAW_POSITIONS) uniform sampler2D u_positions;  // xyz m, w kind

layout(push_constant) uniform WhitewaterDrawBlock {
  WhitewaterDrawPush pc;
};

layout(location = 0) flat out vec4 v_color;  // rgb display-referred, a opacity

void main() {
  ivec2 texel = ivec2(gl_VertexIndex % pc.texture_width, gl_VertexIndex / pc.texture_width);
  vec4 p = texelFetch(u_positions, texel, 0);
  int kind = int(p.w);
  if (kind == LIQUID_WHITEWATER_FREE) {
    gl_Position = vec4(0.0, 0.0, -2.0, 1.0);  // clipped
    gl_PointSize = 1.0;
    v_color = vec4(0.0);
    return;
  }
  vec3 position = p.xyz;
  if (kind == LIQUID_WHITEWATER_BUBBLE) {
    position += pc.toward_camera * pc.bubble_lift;
    v_color = vec4(0.78, 0.9, 1.0, 0.45);
  } else if (kind == LIQUID_WHITEWATER_SPRAY) {
    v_color = vec4(0.9, 0.95, 1.0, 0.75);
  } else {
    v_color = vec4(0.97, 0.98, 1.0, 0.9);
  }
  gl_Position = pc.view_projection * vec4(position, 1.0);
  gl_PointSize = clamp(2.0 * pc.radius * pc.focal_pixels / max(gl_Position.w, 1e-4), 1.0, 32.0);
}
