#version 450
// Splat pass (section 3), vertex stage: one point per active particle, fetched from the particle
// textures by gl_VertexIndex (no vertex buffer). In 3D each particle is drawn once per slice it
// can touch (instance i = the i-th such slice); the point size is the kernel's chord in that slice,
// so the rasterizer visits exactly the cells within radius r. The point reaches its slice by the
// path of liquid/solver/grid_layout.h: gl_Layer written here (vertex-layer), a geometry shader given the
// slice (GEOMETRY_LAYER=1, splat.geom), or the slice's tile of the atlas (ATLAS=1).
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

// Two varyings, not more: lavapipe sets up every varying of every point.
layout(location = 0) flat out vec4 v_point;     // xy particle in target pixels (cells; the atlas's
                                                // texels there), z 1 - dz^2/r^2 (dz: slice offset,
                                                // 0 in 2D), w 1/r^2 (cells^-2)
layout(location = 1) flat out vec3 v_velocity;  // m/s (with the affine transfer: at the point's slice)
#if GEOMETRY_LAYER
layout(location = 2) flat out vec3 v_route;     // x the slice (-1: dropped), yz the chord in clip units
#endif
#if AFFINE
// The affine transfer: C_p's columns (1/s), and its x and y columns times h for the fragment, which
// adds C_p (x_i - x_p) to the velocity it deposits (its z part is the slice's, added here).
layout(set = 0, binding = LIQUID_BINDING_SPLAT_AFFINE) uniform sampler2D u_affine0;
#if DIM == 3
layout(set = 0, binding = LIQUID_BINDING_SPLAT_AFFINE + 1) uniform sampler2D u_affine1;
layout(set = 0, binding = LIQUID_BINDING_SPLAT_AFFINE + 2) uniform sampler2D u_affine2;
#endif
layout(location = 3) flat out vec3 v_affine_x;  // m/s per cell
layout(location = 4) flat out vec3 v_affine_y;
#endif

void main() {
  int width = u.particle_texture_width;
  ivec2 texel = ivec2(gl_VertexIndex % width, gl_VertexIndex / width);
  vec3 position = texelFetch(u_positions, texel, 0).xyz;
  v_velocity = texelFetch(u_velocities, texel, 0).xyz;
  vec3 g = position / cell_size();  // cell c spans [c, c + 1), centre c + 0.5
#if AFFINE && DIM == 3
  v_affine_x = texelFetch(u_affine0, texel, 0).xyz * cell_size();
  v_affine_y = texelFetch(u_affine1, texel, 0).xyz * cell_size();
#elif AFFINE
  vec4 affine = texelFetch(u_affine0, texel, 0);
  v_affine_x = vec3(affine.xy, 0.0) * cell_size();
  v_affine_y = vec3(affine.zw, 0.0) * cell_size();
#endif
  float r = u.kernel_radius;
  float chord = r;
  float dz2 = 0.0;
  vec2 target = g.xy;                     // the point's centre in the target's pixels
  vec2 target_size = vec2(u.grid_cells.xy);
#if DIM == 3
  // Slices whose centre L + 0.5 lies within r of the particle: L in (g.z - r - 0.5, g.z + r - 0.5),
  // at most ceil(2 r) consecutive layers starting here (6 for r = 3).
  int layer = int(floor(g.z - r - 0.5)) + 1 + gl_InstanceIndex;
  float dz = float(layer) + 0.5 - g.z;
  if (layer < 0 || layer >= u.grid_cells.z || abs(dz) >= r) {
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
  dz2 = dz * dz;
#if AFFINE
  v_velocity += texelFetch(u_affine2, texel, 0).xyz * (dz * cell_size());
#endif
  chord = sqrt(r * r - dz2);
#endif
  v_point = vec4(target, 1.0 - dz2 / (r * r), 1.0 / (r * r));
  gl_Position = vec4(target / target_size * 2.0 - 1.0, 0.5, 1.0);
  // Pixel centres within `chord` of the particle on both axes are covered.
  gl_PointSize = 2.0 * chord;
#if GEOMETRY_LAYER
  v_route.yz = 2.0 * chord / target_size;
#endif
}
