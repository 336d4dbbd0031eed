#version 450
// The host's own geometry, made from gl_VertexIndex: a floor (2 triangles) then a box (12).
layout(push_constant) uniform ScenePush {
  mat4 view_projection;
  vec4 box_center;       // xyz m
  vec4 box_half_extent;  // xyz m
  vec4 floor_extent;     // xy: the floor spans [-x, 2x] x [-y, 2y] around the tank, m
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
  vec3 p;
  if (v < 6) {
    vec2 q = k_quad[v] * 0.5 + 0.5;  // 0..1
    vec2 lo = -pc.floor_extent.xy, hi = 2.0 * pc.floor_extent.xy;
    p = vec3(mix(lo.x, hi.x, q.x), 0.0, mix(lo.y, hi.y, q.y));
    v_normal = vec3(0, 1, 0);
    v_is_box = 0;
  } else {
    int face = (v - 6) / 6, corner = (v - 6) % 6;
    ivec3 axes = k_face_axes[face];
    float side = (face % 2 == 0) ? 1.0 : -1.0;
    vec2 q = k_quad[corner];
    vec3 local;
    local[axes.x] = q.x;
    local[axes.y] = q.y;
    local[axes.z] = side;
    vec3 n = vec3(0.0);
    n[axes.z] = side;
    p = pc.box_center.xyz + local * pc.box_half_extent.xyz;
    v_normal = n;
    v_is_box = 1;
  }
  v_world = p;
  gl_Position = pc.view_projection * vec4(p, 1.0);
}
