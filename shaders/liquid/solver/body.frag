#version 450
// Body integration pass: one fragment per texel of the body-state texture (shared.h), each
// computing its body's whole step and writing its own part. Semi-implicit Euler with an added-mass
// term (docs/physics.md, "Bodies that float"):
//   (m + m_a) a' = F_liquid + m g + F_host + m_a a       (a: the last step's acceleration)
//   v' = v + dt a',  x' = x + dt v'
// and the same for rotation in the world frame (I_w = R I R^T, added inertia m_a / m of it):
//   (1 + k) I_w alpha' = tau_liquid + tau_host - w x I_w w + k I_w alpha,  w' = w + dt alpha',
//   q' = normalize(q + dt/2 (w', 0) q).
// With m_a = 0 a light body in dense liquid is unstable (the liquid answers each step's velocity
// with the opposite impulse); the term keeps the steady state (a' = a gives m a = the forces) and
// damps the step-to-step overshoot. Then contact with the walls: the body is kept inside the
// domain and loses its velocity into a wall (no friction, no contact torque).
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#define LIQUID_BODY_STATE_ONLY  // no distances: no body shapes
#include "liquid/common.glsl"

#ifndef PROJECTION
#define PROJECTION 0
#endif

layout(set = 0, binding = LIQUID_BINDING_BODY_FORCE) uniform sampler2D u_force;
layout(set = 0, binding = LIQUID_BINDING_BODY_TORQUE) uniform sampler2D u_torque;
layout(location = 0) in vec2 v_uv;  // the full-screen pair's; unused
layout(location = 0) out vec4 out_state;

vec4 quat_multiply(vec4 a, vec4 b) {
  return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}
// I_w x and I_w^-1 x for the principal moments `inertia` in the body frame q.
vec3 inertia_times(vec4 q, vec3 inertia, vec3 x) { return quat_rotate(q, inertia * quat_rotate_inverse(q, x)); }
vec3 inertia_solve(vec4 q, vec3 inertia, vec3 x) { return quat_rotate(q, quat_rotate_inverse(q, x) / inertia); }

// Half the body's extent along each world axis (its bounding box), for the wall contact.
vec3 world_half_extent(int i, vec4 q) {
  if (obstacle_kind(i) == LIQUID_OBSTACLE_SPHERE) return vec3(u.obstacles[i].sphere_radius);
  vec3 e = u.obstacles[i].box_half_extent;
  return abs(quat_rotate(q, vec3(e.x, 0.0, 0.0))) + abs(quat_rotate(q, vec3(0.0, e.y, 0.0))) +
         abs(quat_rotate(q, vec3(0.0, 0.0, e.z)));
}

// A box against the wall of `axis` on `side` (-1 the low one) under the projection, `gap` short of
// it: the corners past that plane are moved back (the centre with them), and the box meets the wall
// at its corners, not at its centre. The contact point is the corners' mean weighted by how far each
// is past the plane; if it moves into the wall, an impulse along the wall's normal there stops it
// (inelastic, no friction), with the added mass and inertia. A box tilted on the floor then turns
// back about its lower corner as the liquid presses it down, instead of being free to tip over: the
// centre's stop gave no torque, and the liquid's own torque on a box resting half a cell above the
// floor tipped it over (docs/physics.md, "Bodies under the projection").
void box_wall_contact(int i, Body b, vec4 q, int axis, int side, float gap, inout vec3 x, inout vec3 v, inout vec3 w) {
  const vec3 e = u.obstacles[i].box_half_extent;
  const float wall = side < 0 ? gap : u.domain[axis] - gap;
  float deepest = 0.0, weight = 0.0;
  vec3 point = vec3(0.0);
  [[unroll]] for (int k = 0; k < (DIM == 3 ? 8 : 4); ++k) {
    const vec3 corner_sign = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, DIM == 3 && (k & 4) != 0 ? 1.0 : -1.0);
    const vec3 corner = x + quat_rotate(q, corner_sign * e);
    const float past = side < 0 ? wall - corner[axis] : corner[axis] - wall;
    deepest = max(deepest, past);
    if (past > 0.0) {
      point += past * corner;
      weight += past;
    }
  }
  if (weight <= 0.0) return;
  point /= weight;
  x[axis] -= float(side) * deepest;
  vec3 n = vec3(0.0);
  n[axis] = -float(side);  // into the domain
  const vec3 r = point - x;
  const float into = dot(v + cross(w, r), n);
  if (into >= 0.0) return;
  const float mass = b.mass + b.added_mass;
  const vec3 inertia = b.inertia * (1.0 + b.added_inertia_ratio);
  const vec3 turn = inertia_solve(q, inertia, cross(r, n));  // I^-1 (r x n)
  const float impulse = -into / (1.0 / mass + dot(n, cross(turn, r)));
  v += impulse * n / mass;
  w += impulse * turn;
#if DIM == 2
  w.xy = vec2(0.0);
#endif
}

void main() {
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  const int i = texel.y;
  if (!obstacle_dynamic(i)) {
    out_state = body_texel(i, texel.x);
    return;
  }
  const Body b = u.bodies[i];
  const float dt = u.dt;
  vec3 x = body_texel(i, LIQUID_BODY_POSITION).xyz;
  vec4 q = body_texel(i, LIQUID_BODY_ORIENTATION);
  const vec3 v0 = body_texel(i, LIQUID_BODY_VELOCITY).xyz;
  vec3 w = body_texel(i, LIQUID_BODY_ANGULAR_VELOCITY).xyz;
  const vec3 a0 = body_texel(i, LIQUID_BODY_ACCELERATION).xyz;
  const vec3 alpha0 = body_texel(i, LIQUID_BODY_ANGULAR_ACCELERATION).xyz;
  const vec3 force = texelFetch(u_force, ivec2(0, i), 0).xyz;
  const vec3 torque = texelFetch(u_torque, ivec2(0, i), 0).xyz;

  vec3 a = (force + b.mass * u.gravity + b.external_force + b.added_mass * a0) / (b.mass + b.added_mass);
  const float k = b.added_inertia_ratio;
  vec3 alpha = inertia_solve(q, b.inertia,
                             torque + b.external_torque - cross(w, inertia_times(q, b.inertia, w)) +
                                 k * inertia_times(q, b.inertia, alpha0)) / (1.0 + k);
#if DIM == 2
  a.z = 0.0;
  alpha.xy = vec2(0.0);
#endif
  vec3 v = v0 + dt * a;
  x += dt * v;
  w += dt * alpha;
  q = normalize(q + 0.5 * dt * quat_multiply(vec4(w, 0.0), q));

  // Walls. Under the projection the body stops the particles' skin short of a wall: closer, the
  // cells between turn solid (their centres inside the body), and the liquid squeezed from them as
  // the gap closed asked forces of the body that the explicit coupling could not follow (a dense
  // box on the floor was thrown up at 3 m/s: docs/physics.md, "Bodies under the projection").
  const vec3 e = world_half_extent(i, q) + (PROJECTION != 0 ? LIQUID_OBSTACLE_SKIN_CELLS * cell_size() : 0.0);
  const vec3 v_free = v;
  const bool box_contact = PROJECTION != 0 && obstacle_kind(i) == LIQUID_OBSTACLE_BOX;
  [[unroll]] for (int axis = 0; axis < DIM; ++axis) {
    if (box_contact) {
      box_wall_contact(i, b, q, axis, -1, LIQUID_OBSTACLE_SKIN_CELLS * cell_size(), x, v, w);
      box_wall_contact(i, b, q, axis, 1, LIQUID_OBSTACLE_SKIN_CELLS * cell_size(), x, v, w);
      continue;
    }
    const float lo = e[axis], hi = u.domain[axis] - e[axis];
    if (x[axis] < lo) {
      x[axis] = lo;
      v[axis] = max(v[axis], 0.0);
    } else if (x[axis] > hi) {
      x[axis] = hi;
      v[axis] = min(v[axis], 0.0);
    }
  }
  // The acceleration the added-mass term carries into the next step is the forces' (a), not the
  // wall's: along an axis where the wall took velocity away it is 0 (held, as at rest on the floor).
  // Stored as (v - v0) / dt it held the contact's stop, -v0 / dt, and the term gave it back over
  // the next steps as a push off the wall, m_a / m times the speed it arrived with (5 for the boat).
  const vec3 a_kept = mix(a, vec3(0.0), notEqual(v, v_free));

  vec4 state[LIQUID_BODY_TEXELS];
  state[LIQUID_BODY_POSITION] = vec4(x, 1.0);
  state[LIQUID_BODY_ORIENTATION] = q;
  state[LIQUID_BODY_VELOCITY] = vec4(v, 0.0);
  state[LIQUID_BODY_ANGULAR_VELOCITY] = vec4(w, 0.0);
  state[LIQUID_BODY_FORCE] = vec4(force, 0.0);
  state[LIQUID_BODY_TORQUE] = vec4(torque, 0.0);
  state[LIQUID_BODY_ACCELERATION] = vec4(a_kept, 0.0);
  state[LIQUID_BODY_ANGULAR_ACCELERATION] = vec4(alpha, 0.0);
  out_state = state[texel.x];
}
