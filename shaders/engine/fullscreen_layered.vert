#version 450
// Full-screen triangle for layered passes: one instance per layer; the geometry shader
// (fullscreen_layered.geom) routes instance i to layer i of a 3D or array target.
layout(location = 0) out vec2 v_uv;
layout(location = 1) flat out int v_layer;

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  v_uv = corner;
  v_layer = gl_InstanceIndex;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
