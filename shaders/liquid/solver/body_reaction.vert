#version 450
// Body reaction pass: the liquid's force and torque on one dynamic obstacle (the push constant's),
// reduced on the raster pipeline: one point per particle, additively blended into the obstacle's
// texel of two 1 x N targets (force, torque); particles the body did not touch are clipped away.
// What a particle gives is the exact opposite of what the body did to it this step. The particle
// pass gives particle p the grid's u' at x_p (section 5.1: both the PIC and the FLIP term carry
// u'(x_p) with weight 1), and u' is the grid pass's update with the body's artificial density and
// no-inflow condition; body_grid.frag's u'_b is the same update without the body. So
//   F_body = -sum_p m (u'(x_p) - u'_b(x_p)) / dt,   tau = sum_p (x_p - x_body) x f_p,
// and the body's momentum change is the liquid's, with the sign turned (docs/physics.md, "Bodies
// that float"). (The particle pass moves particles out of the body without touching their velocity.)
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_sample.glsl"

layout(set = 0, binding = LIQUID_BINDING_PARTICLE_POSITIONS) uniform sampler2D u_positions;
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_GRID_VELOCITY) uniform GRID_SAMPLER u_velocity;  // u'
layout(set = 0, binding = LIQUID_BINDING_BODY_GRID_VELOCITY) uniform GRID_SAMPLER u_without;      // u'_b

layout(push_constant) uniform BodyReactionPush {
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
  vec3 with_body, without_body, unused;
  sample_grid(u_velocity, u_velocity, x, false, with_body, unused);
  sample_grid(u_without, u_without, x, false, without_body, unused);
  const vec3 change = with_body - without_body;
  if (dot(change, change) == 0.0) return;
  v_force = -pc.particle_mass * change / u.dt;
  v_torque = cross(x - obstacle_frame(pc.body).center, v_force);
  gl_Position = vec4(0.0, (float(pc.body) + 0.5) / float(obstacle_count()) * 2.0 - 1.0, 0.0, 1.0);
}
