#version 450
// The 3D view's mesh obstacles (liquid/render/mesh_draw.h): each triangle's corners fetched from
// the mesh's triangle texture by gl_VertexIndex, placed by its transform, flat-shaded by the face
// normal.
#extension GL_GOOGLE_include_directive : require
#include "liquid/shared.h"

layout(set = 0, binding = LIQUID_BINDING_MESH_TRIANGLES) uniform sampler2D u_triangles;
layout(push_constant) uniform Push {
  MeshDrawPush pc;
};
layout(location = 0) flat out vec3 v_normal;

vec3 corner(int i) {
  vec4 local = vec4(texelFetch(u_triangles, ivec2(i % LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH,
                                                  i / LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH), 0).xyz, 1.0);
  return vec3(dot(pc.model_rows[0], local), dot(pc.model_rows[1], local), dot(pc.model_rows[2], local));
}

void main() {
  int first = 3 * (gl_VertexIndex / 3);
  vec3 a = corner(first), b = corner(first + 1), c = corner(first + 2);
  v_normal = normalize(cross(b - a, c - a));
  gl_Position = pc.view_projection * vec4(corner(gl_VertexIndex), 1.0);
}
