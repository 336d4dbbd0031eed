#version 450
// Mesh obstacles' voxelization (liquid/solver/mesh_field.h), vertex stage of its two raster passes.
// The triangles' corners are fetched from a texture by gl_VertexIndex (3 texels per triangle, the
// mesh's own frame) and placed by the push constants' transform; the grid is looked at along z, one
// instance per slice, routed to its slice as the splat is (GEOMETRY_LAYER: mesh_raster.geom; ATLAS:
// the slice's tile; else gl_Layer here).
//   SEED=0 (inside): the triangle itself, in each slice s whose span between cell centres
//                    (s + 0.5, s + 1.5] it crosses; mesh_inside.frag counts the crossings there,
//                    and the field pass sums them from a cell up.
//   SEED=1 (seed):   per triangle, in each slice within LIQUID_MESH_SEED_CELLS of it, the rectangle
//                    of cells within that of its part in the slice's slab (drawn as one triangle
//                    holding it); mesh_seed.frag takes the exact closest point.
#ifndef GEOMETRY_LAYER
#define GEOMETRY_LAYER 0
#endif
#ifndef ATLAS
#define ATLAS 0
#endif
#if DIM == 3 && !ATLAS && !GEOMETRY_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(set = 0, binding = LIQUID_BINDING_MESH_TRIANGLES) uniform sampler2D u_triangles;
layout(push_constant) uniform Push {
  MeshRasterPush pc;
};

#if SEED
layout(location = 0) flat out vec3 v_a;  // the triangle, world (m)
layout(location = 1) flat out vec3 v_b;
layout(location = 2) flat out vec3 v_c;
#else
layout(location = 0) out float v_z;      // the surface's z (m)
#endif
layout(location = 3) flat out int v_slice;  // -1: dropped (the geometry shader emits nothing)

vec3 corner(int triangle, int k) {
  int i = 3 * triangle + k;
  ivec2 texel = ivec2(i % LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH, i / LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH);
  return (pc.local_to_world * vec4(texelFetch(u_triangles, texel, 0).xyz, 1.0)).xyz;
}

// Clip position of point `g` (cells) of slice `slice`.
vec4 clip_position(vec2 g, int slice) {
  vec2 target = g;
  vec2 size = vec2(grid_cells().xy);
#if DIM == 3 && ATLAS
  target += vec2(atlas_tile_origin(slice, grid_cells(), atlas_tiles()));
  size *= vec2(atlas_tiles());
#endif
  return vec4(target / size * 2.0 - 1.0, 0.5, 1.0);
}

void route(int slice) {
  v_slice = slice;
#if DIM == 3 && !ATLAS && !GEOMETRY_LAYER
  gl_Layer = max(slice, 0);
#endif
}

void drop() {
  gl_Position = vec4(-4.0, -4.0, 0.5, 1.0);  // outside the clip volume
  route(-1);
}

#if SEED
// Grows the box [lo, hi] to hold p.
void include(vec2 p, inout vec2 lo, inout vec2 hi) {
  lo = min(lo, p);
  hi = max(hi, p);
}

// The xy box of the part of triangle (a, b, c) with z in [z0, z1] (all in cells): its corners
// there and its edges' crossings of the two planes; false if no part lies there.
bool slab_box(vec3 a, vec3 b, vec3 c, float z0, float z1, out vec2 lo, out vec2 hi) {
  lo = vec2(1.0e30);
  hi = vec2(-1.0e30);
  vec3 corners[3] = vec3[3](a, b, c);
  for (int i = 0; i < 3; ++i) {
    vec3 p = corners[i], q = corners[(i + 1) % 3];
    if (p.z >= z0 && p.z <= z1) include(p.xy, lo, hi);
    for (int k = 0; k < 2; ++k) {
      float plane = k == 0 ? z0 : z1;
      if ((p.z - plane) * (q.z - plane) < 0.0) include(mix(p.xy, q.xy, (plane - p.z) / (q.z - p.z)), lo, hi);
    }
  }
  return lo.x <= hi.x;
}
#endif

void main() {
  float h = cell_size();
#if SEED
  int triangle = gl_VertexIndex / 3;
  int k = gl_VertexIndex % 3;
  v_a = corner(triangle, 0);
  v_b = corner(triangle, 1);
  v_c = corner(triangle, 2);
  float r = LIQUID_MESH_SEED_CELLS;
#if DIM == 3
  // Slices whose centre s + 0.5 lies within r of the triangle's z range: instance i is the i-th from the lowest.
  float low = min(v_a.z, min(v_b.z, v_c.z)) / h;
  int slice = int(ceil(low - r - 0.5)) + gl_InstanceIndex;
  float centre = float(slice) + 0.5;
#else
  int slice = 0;
  float centre = 0.0;  // the plane z = 0
#endif
  vec2 lo, hi;
  if (slice < 0 || slice >= grid_cells().z || !slab_box(v_a / h, v_b / h, v_c / h, centre - r, centre + r, lo, hi)) {
    drop();
    return;
  }
  lo = clamp(lo - r, vec2(0.0), vec2(grid_cells().xy));
  hi = clamp(hi + r, vec2(0.0), vec2(grid_cells().xy));
  if (lo.x >= hi.x || lo.y >= hi.y) {
    drop();
    return;
  }
  // One triangle holding the rectangle, corners (0,0) (2,0) (0,2) of it: half the vertices and
  // primitives of two, which are most of the pass's cost; the cells it covers beyond the rectangle
  // are seeded as well (or, in the atlas, dropped by mesh_fragment_cell as another slice's).
  vec2 uv = vec2(k == 1 ? 2.0 : 0.0, k == 2 ? 2.0 : 0.0);
  gl_Position = clip_position(mix(lo, hi, uv), slice);
  route(slice);
#else
  int triangle = gl_VertexIndex / 3;
  vec3 p = corner(triangle, gl_VertexIndex % 3);
  v_z = p.z;
#if DIM == 3
  // The slices whose span (s + 0.5, s + 1.5] (cells) the triangle's z range meets; the top slice
  // also takes what lies above the grid.
  vec3 a = corner(triangle, 0), b = corner(triangle, 1), c = corner(triangle, 2);
  int top = grid_cells().z - 1;
  int lowest = min(int(floor(min(a.z, min(b.z, c.z)) / h - 0.5)), top);
  int highest = min(int(floor(max(a.z, max(b.z, c.z)) / h - 0.5)), top);
  int slice = max(lowest, 0) + gl_InstanceIndex;
  if (slice > highest) {
    drop();
    return;
  }
#else
  int slice = 0;
#endif
  gl_Position = clip_position(p.xy / h, slice);
  route(slice);
#endif
}
