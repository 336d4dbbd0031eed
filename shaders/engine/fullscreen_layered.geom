#version 450
// Routes the full-screen triangle of instance i to layer (slice) i; the fragment shader gets the
// slice in v_layer. Geometry shaders are the layered-rendering path the chapter uses (SM 4).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec2 v_uv_in[];
layout(location = 1) flat in int v_layer_in[];
layout(location = 0) out vec2 v_uv;
layout(location = 1) flat out int v_layer;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    v_uv = v_uv_in[i];
    v_layer = v_layer_in[i];
    gl_Layer = v_layer_in[i];
    EmitVertex();
  }
  EndPrimitive();
}
