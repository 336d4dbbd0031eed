#version 450
// Splat pass on the geometry-shader path (liquid/solver/grid_layout.h), for devices with geometry shaders
// but without shaderOutputLayer: routes each point of splat.vert (GEOMETRY_LAYER=1) to its slice
// with gl_Layer. It emits the point's square as two triangles rather than a point, since writing
// gl_PointSize here would need one more device feature (shaderTessellationAndGeometryPointSize);
// the square covers the pixel centres within the chord on both axes, as the point does.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
layout(location = 0) flat in vec4 v_point_in[];
layout(location = 1) flat in vec3 v_velocity_in[];
layout(location = 2) flat in vec3 v_route_in[];
layout(location = 0) flat out vec4 v_point;
layout(location = 1) flat out vec3 v_velocity;
#ifndef AFFINE
#define AFFINE 0
#endif
#if AFFINE
layout(location = 3) flat in vec3 v_affine_x_in[];
layout(location = 4) flat in vec3 v_affine_y_in[];
layout(location = 3) flat out vec3 v_affine_x;
layout(location = 4) flat out vec3 v_affine_y;
#endif

void main() {
  if (v_route_in[0].x < 0.0) return;  // the slice is out of the kernel's reach
  vec2 half_extent = v_route_in[0].yz;  // the chord in clip units
  for (int i = 0; i < 4; ++i) {
    vec2 corner = vec2(i & 1, i >> 1) * 2.0 - 1.0;
    gl_Position = gl_in[0].gl_Position + vec4(corner * half_extent, 0.0, 0.0);
    gl_Layer = int(v_route_in[0].x);
    v_point = v_point_in[0];
    v_velocity = v_velocity_in[0];
#if AFFINE
    v_affine_x = v_affine_x_in[0];
    v_affine_y = v_affine_y_in[0];
#endif
    EmitVertex();
  }
  EndPrimitive();
}
