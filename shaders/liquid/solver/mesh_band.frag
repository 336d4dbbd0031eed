#version 450
// Mesh voxelization, band pass: the exact distance from the cell's centre to one triangle, kept
// where it is the smallest so far by MIN blending; the other channels get the cleared value, which
// leaves them as they are.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/mesh_cell.glsl"

layout(location = 0) flat in vec3 v_a;
layout(location = 1) flat in vec3 v_b;
layout(location = 2) flat in vec3 v_c;
layout(location = 3) flat in int v_slice;
layout(location = 0) out vec4 out_distance;

// Closest distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5;
// the CPU's twin is liquid/physics/mesh.cpp).
float triangle_distance(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return length(ap);
  vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return length(bp);
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return length(ap - ab * (d1 / (d1 - d3)));
  vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return length(cp);
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return length(ap - ac * (d2 / (d2 - d6)));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return length(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  float denom = 1.0 / (va + vb + vc);
  return length(ap - ab * (vb * denom) - ac * (vc * denom));
}

void main() {
  ivec3 c;
  if (!mesh_fragment_cell(v_slice, c)) discard;
  out_distance = vec4(LIQUID_MESH_FAR);
  out_distance[pc.slot] = triangle_distance(cell_center(c), v_a, v_b, v_c);
}
