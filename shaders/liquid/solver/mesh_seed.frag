#version 450
// Mesh voxelization, seed pass: the exact closest point of one triangle to the cell's centre, kept
// where it is the closest so far by the depth test (depth: its distance over the band); the spread
// passes (mesh_spread.frag) carry the closest points on to the rest of the band.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/mesh_cell.glsl"

layout(location = 0) flat in vec3 v_a;
layout(location = 1) flat in vec3 v_b;
layout(location = 2) flat in vec3 v_c;
layout(location = 3) flat in int v_slice;
layout(location = 0) out vec4 out_nearest;  // xyz: the point (m); w unused

// Closest point to p on the triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5;
// the CPU's twin is liquid/physics/mesh.cpp).
vec3 triangle_closest_point(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  float denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

void main() {
  ivec3 c;
  if (!mesh_fragment_cell(v_slice, c)) discard;
  vec3 p = cell_center(c);
  vec3 q = triangle_closest_point(p, v_a, v_b, v_c);
  gl_FragDepth = min(length(p - q) / pc.band, 1.0);
  out_nearest = vec4(q, 0.0);
}
