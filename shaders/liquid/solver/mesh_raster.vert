#version 450
// Mesh obstacles' voxelization (liquid/solver/mesh_field.h), vertex stage of its two raster passes.
// The triangles' corners are fetched from a texture by gl_VertexIndex (3 texels per triangle, the
// mesh's own frame) and placed by the push constants' transform; the grid is looked at along z, one
// instance per slice, routed to its slice as the splat is (GEOMETRY_LAYER: mesh_raster.geom; ATLAS:
// the slice's tile; else gl_Layer here).
//   BAND=0 (inside): the triangle itself, in every slice of the mesh's z range from first_slice;
//                    mesh_inside.frag counts the surfaces above each cell.
//   BAND=1 (band):   per triangle, in each slice within `band` of it, the rectangle of cells within
//                    `band` of its bounding box there; mesh_band.frag takes the exact distance.
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

#if BAND
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

void main() {
  float h = cell_size();
#if BAND
  int triangle = gl_VertexIndex / 6;
  int k = gl_VertexIndex % 6;
  v_a = corner(triangle, 0);
  v_b = corner(triangle, 1);
  v_c = corner(triangle, 2);
  float band = pc.band / h;
  vec3 lo = min(v_a, min(v_b, v_c)) / h;  // the triangle's box, cells
  vec3 hi = max(v_a, max(v_b, v_c)) / h;
#if DIM == 3
  // Slices whose centre s + 0.5 lies within the band of the box: instance i is the i-th from the lowest.
  int slice = int(ceil(lo.z - band - 0.5)) + gl_InstanceIndex;
  float centre = float(slice) + 0.5;
#else
  int slice = 0;
  float centre = 0.0;  // the plane z = 0
#endif
  // The band's section in this slice: the box grown by what is left of the band after the step
  // from the slice to the box along z (a ball's chord), about half the cells of the full box.
  float dz = max(max(lo.z - centre, centre - hi.z), 0.0);
  if (slice < 0 || slice >= grid_cells().z || dz >= band) {
    drop();
    return;
  }
  float reach = sqrt(band * band - dz * dz);
  lo.xy -= reach;
  hi.xy += reach;
  lo.xy = clamp(lo.xy, vec2(0.0), vec2(grid_cells().xy));
  hi.xy = clamp(hi.xy, vec2(0.0), vec2(grid_cells().xy));
  if (lo.x >= hi.x || lo.y >= hi.y) {
    drop();
    return;
  }
  // Two triangles: corners (0,0) (1,0) (0,1) and (1,0) (1,1) (0,1).
  vec2 uv = vec2(k == 1 || k == 3 || k == 4 ? 1.0 : 0.0, k == 2 || k == 4 || k == 5 ? 1.0 : 0.0);
  gl_Position = clip_position(mix(lo.xy, hi.xy, uv), slice);
  route(slice);
#else
  vec3 p = corner(gl_VertexIndex / 3, gl_VertexIndex % 3);
  int slice = DIM == 3 ? pc.first_slice + gl_InstanceIndex : 0;
  v_z = p.z;
  gl_Position = clip_position(p.xy / h, slice);
  route(slice);
#endif
}
