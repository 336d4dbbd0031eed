#version 450
// The host's own geometry, made from gl_VertexIndex: a floor (vertices 0-5, the square [-1, 1]^2 at
// y = 0) and a box (vertices 6-41, the cube [-1, 1]^3), each placed in the world by `model`.
layout(push_constant) uniform ScenePush {
  mat4 view_projection;  // the host's camera: reversed Z
  mat4 model;            // this draw's placement in the world
} pc;

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;
layout(location = 2) flat out int v_is_box;

// Corner i of a unit cube's face f (two triangles), and the face's normal.
const ivec3 k_face_axes[6] = ivec3[](ivec3(0, 1, 2), ivec3(0, 1, 2), ivec3(1, 2, 0), ivec3(1, 2, 0),
                                     ivec3(2, 0, 1), ivec3(2, 0, 1));
const vec2 k_quad[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
  int v = gl_VertexIndex;
  vec3 local, normal;
  if (v < 6) {
    local = vec3(k_quad[v].x, 0.0, k_quad[v].y);
    normal = vec3(0, 1, 0);
    v_is_box = 0;
  } else {
    int face = (v - 6) / 6, corner = (v - 6) % 6;
    ivec3 axes = k_face_axes[face];
    float side = (face % 2 == 0) ? 1.0 : -1.0;
    local[axes.x] = k_quad[corner].x;
    local[axes.y] = k_quad[corner].y;
    local[axes.z] = side;
    normal = vec3(0.0);
    normal[axes.z] = side;
    v_is_box = 1;
  }
  vec4 world = pc.model * vec4(local, 1.0);
  v_world = world.xyz;
  v_normal = normalize(mat3(pc.model) * normal);  // rotation and uniform scale: no inverse transpose
  gl_Position = pc.view_projection * world;
}
