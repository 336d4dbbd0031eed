#version 450
// Full-screen triangle from gl_VertexIndex alone (no vertex buffer): draw 3 vertices.
// v_uv is (0,0) at the top-left texel corner and (1,1) at the bottom-right.
layout(location = 0) out vec2 v_uv;

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
