#version 450
// Mesh voxelization on the geometry-shader path: routes mesh_raster.vert's triangles (GEOMETRY_LAYER=1)
// to their slice with gl_Layer, corners in order (the inside pass's facing is kept).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
#if SEED
layout(location = 0) flat in vec3 v_a_in[];
layout(location = 1) flat in vec3 v_b_in[];
layout(location = 2) flat in vec3 v_c_in[];
layout(location = 0) flat out vec3 v_a;
layout(location = 1) flat out vec3 v_b;
layout(location = 2) flat out vec3 v_c;
#else
layout(location = 0) in float v_z_in[];
layout(location = 0) out float v_z;
#endif
layout(location = 3) flat in int v_slice_in[];
layout(location = 3) flat out int v_slice;

void main() {
  if (v_slice_in[0] < 0) return;
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    gl_Layer = v_slice_in[0];
    v_slice = v_slice_in[0];
#if SEED
    v_a = v_a_in[0];
    v_b = v_b_in[0];
    v_c = v_c_in[0];
#else
    v_z = v_z_in[i];
#endif
    EmitVertex();
  }
  EndPrimitive();
}
