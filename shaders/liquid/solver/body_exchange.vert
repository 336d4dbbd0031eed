#version 450
// Body exchange pass: the momentum a dynamic obstacle (the push constant's) gives the liquid it runs
// into, whose opposite is added to its pressure force (body_force.vert): one point per particle,
// blended into the obstacle's texel of the same two targets; particles it did not touch are
// clipped away. The particle pass gives particle p the grid's u' interpolated over the cells that
// hold liquid; the exchange is the body's condition (obstacle_condition) applied to those cells'
// splatted velocity u, the liquid as it arrives, before this step's pressure and gravity, whose
// part the pressure integral carries (so a body at rest gets none of it):
//   f_p = -m sum_c w_c (C(u_c) - u_c) / dt,   tau = sum_p (x_p - x_body) x f_p
// (docs/physics.md, "Bodies that float").
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_update.glsl"

layout(set = 0, binding = LIQUID_BINDING_BODY_PARTICLES) uniform sampler2D u_positions;

layout(push_constant) uniform BodyExchangePush {
  int body;             // the obstacle
  float particle_mass;  // kg (2D: per metre of depth)
} pc;

layout(location = 0) flat out vec3 v_force;
layout(location = 1) flat out vec3 v_torque;

void main() {
  const int index = gl_VertexIndex;
  const ivec2 texel = ivec2(index % u.particle_texture_width, index / u.particle_texture_width);
  gl_PointSize = 1.0;
  gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // outside the target: clipped
  v_force = vec3(0.0);
  v_torque = vec3(0.0);
  const vec3 x = texelFetch(u_positions, texel, 0).xyz;
  // The condition changes a cell's velocity only within a cell of the body's surface, and the cells
  // below lie within a cell of x along each axis, so within sqrt(DIM) cells of it. A dynamic body's
  // distance (a sphere's or a box's, slope 1; a mesh's, the trilinear body-shape texture's, slope
  // at most sqrt(DIM) times 1.13 for texels within 0.064 texels of the exact distance) drops by
  // less than DIM + 1 cells from x to any of them. Farther out, nothing to do: one distance instead
  // of the 4 or 8 cells' conditions, for most particles of a scene. (Metaballs, whose estimate is
  // not Lipschitz, cannot be dynamic.)
  if (obstacle_distance(pc.body, x) > float(2 + DIM) * cell_size()) return;

  // The cells and weights of sample_grid (grid_sample.glsl): trilinear over the cells with liquid.
  vec3 g = x / cell_size() - 0.5;
  ivec3 base = ivec3(floor(g));
  vec3 f = g - vec3(base);
#if DIM == 3
  const int corners = 8;
#else
  const int corners = 4;
  f.z = 0.0;
  base.z = 0;
#endif
  vec3 change = vec3(0.0);
  float total = 0.0;
  for (int i = 0; i < corners; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 t = mix(1.0 - f, f, vec3(o));
    float weight = t.x * t.y * t.z;
    ivec3 c = clamp(base + o, ivec3(0), grid_cells() - 1);
    vec4 splat = fetch_grid(u_splat, c);
    if (weight <= 0.0 || splat.a <= k_fluid_epsilon) continue;
    vec3 arriving = splat.rgb / splat.a;
    total += weight;
    change += weight * (obstacle_condition(pc.body, cell_center(c), arriving, mesh_sample_at_cell(c, true)) - arriving);
  }
  if (total == 0.0 || dot(change, change) == 0.0) return;
#if DIM == 2
  change.z = 0.0;
#endif
  v_force = -pc.particle_mass * change / (total * u.dt);
  v_torque = cross(x - obstacle_frame(pc.body).center, v_force);
  gl_Position = vec4(0.0, (float(pc.body) + 0.5) / float(obstacle_count()) * 2.0 - 1.0, 0.0, 1.0);
}
