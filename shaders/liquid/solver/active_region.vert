#version 450
// The 3D grid passes' vertex shader when a step computes only its active region
// (liquid/solver/active_region.h): instance i draws the rectangle of cells of band i % bands of
// slice i / bands (two triangles, six vertices), or nothing when the band has none, instead of
// whole slices. On the layered paths
// the slice is a layer: written here as gl_Layer (VERTEX_LAYER=1), or routed by the layered
// full-screen geometry shader from v_layer; on the atlas path the rectangle is placed in the slice's
// tile. The same outputs as the full-screen vertex shaders, so every grid fragment shader runs
// unchanged (grid_fragment.glsl).
#ifndef VERTEX_LAYER
#define VERTEX_LAYER 0
#endif
#if VERTEX_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/grid_atlas.glsl"

layout(set = 0, binding = LIQUID_BINDING_ACTIVE_REGION) uniform sampler2D u_region;

layout(location = 0) out vec2 v_uv;
#if !ATLAS
layout(location = 1) flat out int v_layer;  // the slice, on the layered paths (grid_fragment.glsl)
#endif

const vec2 k_corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
  int bands = textureSize(u_region, 0).x;
  int z = gl_InstanceIndex / bands;
  vec4 rectangle = texelFetch(u_region, ivec2(gl_InstanceIndex - z * bands, z), 0);  // (x0, y0, x1, y1), inclusive
  vec2 lo = rectangle.xy;
  vec2 hi = rectangle.x <= rectangle.z ? rectangle.zw + 1.0 : lo;  // empty: a degenerate pair
  vec2 pixel = mix(lo, hi, k_corners[gl_VertexIndex]);
  vec2 area = vec2(grid_cells().xy);
#if ATLAS
  pixel += vec2(atlas_tile_origin(z, grid_cells(), atlas_tiles()));
  area *= vec2(atlas_tiles());
#endif
  v_uv = pixel / area;
#if !ATLAS
  v_layer = z;
#endif
#if VERTEX_LAYER
  gl_Layer = z;
#endif
  gl_Position = vec4(v_uv * 2.0 - 1.0, 0.0, 1.0);
}
