#version 450
#extension GL_GOOGLE_include_directive : require
#include "host_limits.h"
// The host's own geometry, its vertices pulled from a uniform buffer by the index each indexed draw
// gives (host_mesh.h's layout: position, then normal with the material in w; 32 bytes a vertex),
// each draw placed in the world by `model`.
layout(push_constant) uniform ScenePush {
  mat4 view_projection;  // the host's camera: reversed Z
  mat4 model;            // this draw's placement in the world
} pc;

layout(set = 0, binding = 0) uniform HostVertices { vec4 position_normal[2 * HOST_MAX_VERTICES]; } vertices;

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;
layout(location = 2) flat out int v_material;

void main() {
  vec4 normal = vertices.position_normal[2 * gl_VertexIndex + 1];
  vec4 world = pc.model * vec4(vertices.position_normal[2 * gl_VertexIndex].xyz, 1.0);
  v_material = int(normal.w);
  v_world = world.xyz;
  v_normal = normalize(mat3(pc.model) * normal.xyz);  // rotation and uniform scale: no inverse transpose
  gl_Position = pc.view_projection * world;
}
