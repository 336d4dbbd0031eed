#version 450
// Full-screen triangle for layered passes: one instance per layer. Instance i goes to layer i of a
// 3D or array target: through the geometry shader (fullscreen_layered.geom), or, compiled with
// VERTEX_LAYER=1 for devices with shaderOutputLayer, by writing gl_Layer here.
#ifndef VERTEX_LAYER
#define VERTEX_LAYER 0
#endif
#if VERTEX_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
layout(location = 0) out vec2 v_uv;
layout(location = 1) flat out int v_layer;

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  v_uv = corner;
  v_layer = gl_InstanceIndex;
#if VERTEX_LAYER
  gl_Layer = gl_InstanceIndex;
#endif
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
