#version 450
// Separable splat (scene key "splat": "separable"), deposit stage, vertex shader: one point of two
// cells' width per active particle, covering the 4 cell centres around it in its plane, which
// deposit.frag gives their bilinear weights. In 3D the point goes to the lower of the two slices
// around the particle and writes two targets: the lower slice's share and the upper one's (added
// to the next slice by the z pass, separable_blur.frag with DEPOSIT_PAIR): one point per particle
// instead of one per slice, since on lavapipe a point's cost is mostly per point, not per pixel
// (a point of the kernel's width carrying the in-plane profile, which would save the x and y
// passes, cost more than they do: docs/lavapipe-performance.md). separable_blur.frag then
// spreads the deposit with the kernel's taps along each axis. Same outputs as splat.vert, so the
// geometry-shader path reuses splat.geom.
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

layout(location = 0) flat out vec4 v_point;     // xy particle in target pixels, z the upper slice's
                                                // share (3D; 0 in 2D), w unused
layout(location = 1) flat out vec3 v_velocity;  // m/s
#if GEOMETRY_LAYER
layout(location = 2) flat out vec3 v_route;     // x the slice, yz the half extent in clip units
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
  float upper_share = 0.0;
  vec2 target = g.xy;
  vec2 target_size = vec2(u.grid_cells.xy);
#if DIM == 3
  // The slices whose centres lie below and above the particle, weighted 1 - |dz|: the lower one
  // gets 1 - f, the upper one f (0 for a particle on the top slice's centre).
  int layer = min(int(floor(g.z - 0.5)), u.grid_cells.z - 1);
  upper_share = g.z - 0.5 - float(layer);
#if ATLAS
  target += vec2(atlas_texel(ivec3(0, 0, layer), u.grid_cells, atlas_tiles()));
  target_size *= vec2(atlas_tiles());
#elif GEOMETRY_LAYER
  v_route.x = float(layer);
#else
  gl_Layer = layer;
#endif
#endif
  v_point = vec4(target, upper_share, 0.0);
  gl_Position = vec4(target / target_size * 2.0 - 1.0, 0.5, 1.0);
  gl_PointSize = k_deposit_point_size;
#if GEOMETRY_LAYER
  v_route.yz = k_deposit_point_size / target_size;
#endif
}
