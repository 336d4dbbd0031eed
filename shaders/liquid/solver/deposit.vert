#version 450
// Separable splat (scene key "splat": "separable"), deposit stage, vertex shader: one point of two
// cells' width per active particle (two per particle in 3D, one on each of the two slices around
// it), covering the 2^d cell centres around the particle, which deposit.frag gives their bilinear
// (trilinear in 3D) weights. separable_blur.frag then spreads the deposit with the kernel's taps
// along each axis. Same outputs as splat.vert, so the geometry-shader path reuses splat.geom.
//
// Walls: the position is clamped to the outermost cell centres first. For a particle less than half
// a cell from a wall that moves the weight its bilinear footprint had beyond the wall into the wall
// cell, which is exactly its mirror image's deposit there; with the blur's mirrored taps the grid
// then holds the liquid continued through the wall as its mirror image, the model the point-sprite
// splat's coverage table stands for (liquid/physics/wall_coverage.h), so no coverage correction is
// needed (docs/physics.md, "The separable splat").
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

layout(set = 0, binding = LIQUID_BINDING_SPLAT_POSITIONS) uniform sampler2D u_positions;
layout(set = 0, binding = LIQUID_BINDING_SPLAT_VELOCITIES) uniform sampler2D u_velocities;

layout(location = 0) flat out vec4 v_point;     // xy particle in target pixels, z the slice's weight
                                                // (1 in 2D), w unused
layout(location = 1) flat out vec3 v_velocity;  // m/s
#if GEOMETRY_LAYER
layout(location = 2) flat out vec3 v_route;     // x the slice (-1: dropped), yz the half extent in clip units
#endif

// The deposit reaches the cell centres less than one cell away on each axis: a square of 2 pixels.
const float k_deposit_point_size = 2.0;

void main() {
  int width = u.particle_texture_width;
  ivec2 texel = ivec2(gl_VertexIndex % width, gl_VertexIndex / width);
  vec3 position = texelFetch(u_positions, texel, 0).xyz;
  v_velocity = texelFetch(u_velocities, texel, 0).xyz;
  // In cells, with cell c's centre at c + 0.5; clamped to the outermost centres (the fold above).
  vec3 g = clamp(position / cell_size(), vec3(0.5), vec3(grid_cells()) - 0.5);
  float slice_weight = 1.0;
  vec2 target = g.xy;
  vec2 target_size = vec2(u.grid_cells.xy);
#if DIM == 3
  // The two slices whose centres lie within one cell of the particle, weighted 1 - |dz|.
  int layer = int(floor(g.z - 0.5)) + gl_InstanceIndex;
  slice_weight = 1.0 - abs(float(layer) + 0.5 - g.z);
  if (layer < 0 || layer >= u.grid_cells.z || slice_weight <= 0.0) {
    gl_Position = vec4(-4.0, -4.0, 0.5, 1.0);  // outside the clip volume: the point is dropped
    gl_PointSize = 1.0;
    v_point = vec4(0.0);
#if GEOMETRY_LAYER
    v_route = vec3(-1.0, 0.0, 0.0);
#endif
    return;
  }
#if ATLAS
  target += vec2(atlas_texel(ivec3(0, 0, layer), u.grid_cells, atlas_tiles()));
  target_size *= vec2(atlas_tiles());
#elif GEOMETRY_LAYER
  v_route.x = float(layer);
#else
  gl_Layer = layer;
#endif
#endif
  v_point = vec4(target, slice_weight, 0.0);
  gl_Position = vec4(target / target_size * 2.0 - 1.0, 0.5, 1.0);
  gl_PointSize = k_deposit_point_size;
#if GEOMETRY_LAYER
  v_route.yz = k_deposit_point_size / target_size;
#endif
}
