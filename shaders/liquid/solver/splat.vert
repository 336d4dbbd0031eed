#version 450
// Splat pass (section 3), vertex stage: one point per active particle, fetched from the particle
// textures by gl_VertexIndex (no vertex buffer). In 3D each particle is drawn once per slice it
// can touch (instance i = the i-th such slice) and routed to that slice with gl_Layer; the point size is
// the kernel's chord in that slice, so the rasterizer visits exactly the cells within radius r.
#if DIM == 3
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"

layout(set = 0, binding = LIQUID_BINDING_SPLAT_POSITIONS) uniform sampler2D u_positions;
layout(set = 0, binding = LIQUID_BINDING_SPLAT_VELOCITIES) uniform sampler2D u_velocities;

// Two varyings, not more: lavapipe sets up every varying of every point.
layout(location = 0) flat out vec4 v_point;     // xy particle in grid units (cells), z 1 - dz^2/r^2
                                                // (dz: slice offset, 0 in 2D), w 1/r^2 (cells^-2)
layout(location = 1) flat out vec3 v_velocity;  // m/s

void main() {
  int width = u.particle_texture_width;
  ivec2 texel = ivec2(gl_VertexIndex % width, gl_VertexIndex / width);
  vec3 position = texelFetch(u_positions, texel, 0).xyz;
  v_velocity = texelFetch(u_velocities, texel, 0).xyz;
  vec3 g = position / cell_size();  // cell c spans [c, c + 1), centre c + 0.5
  float r = u.kernel_radius;
  float chord = r;
  float dz2 = 0.0;
#if DIM == 3
  // Slices whose centre L + 0.5 lies within r of the particle: L in (g.z - r - 0.5, g.z + r - 0.5),
  // at most ceil(2 r) consecutive layers starting here (6 for r = 3).
  int layer = int(floor(g.z - r - 0.5)) + 1 + gl_InstanceIndex;
  float dz = float(layer) + 0.5 - g.z;
  if (layer < 0 || layer >= u.grid_cells.z || abs(dz) >= r) {
    gl_Position = vec4(-4.0, -4.0, 0.5, 1.0);  // outside the clip volume: the point is dropped
    gl_PointSize = 1.0;
    v_point = vec4(0.0);
    return;
  }
  gl_Layer = layer;
  dz2 = dz * dz;
  chord = sqrt(r * r - dz2);
#endif
  v_point = vec4(g.xy, 1.0 - dz2 / (r * r), 1.0 / (r * r));
  gl_Position = vec4(g.xy / vec2(u.grid_cells.xy) * 2.0 - 1.0, 0.5, 1.0);
  // Pixel centres within `chord` of the particle on both axes are covered.
  gl_PointSize = 2.0 * chord;
}
