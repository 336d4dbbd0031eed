#version 450
// Whitewater pass: spray, foam and bubbles (Ihmsen et al. 2012, "Unified spray, foam and bubbles for
// particle-based fluids"), one fragment per secondary-particle slot, two render targets (position
// and kind, velocity and birth time). Liquid particle p owns the slots at its texel in each of the
// `slots` blocks of owner_rows rows, so spawning needs no atomics: a free slot spawns from its own
// liquid particle, with a probability from that particle's potentials, and nothing else writes it.
//
// Potentials, from the grids around the liquid particle (x_p, v_p):
//   trapped air  sum_c |v_pc| (1 - v_pc^ . x_pc^) W / sum_c W over the cells c around it that hold
//                liquid, v_pc = v_p - u'_c, x_pc = x_p - x_c: how fast the liquid closes in on it;
//   wave crest   the curvature div n of the density's outward normal where v_p^ . n >= 0.6 (a
//                convex surface moving outward);
//   speed        |v_p|, which scales both.
// Each is mapped linearly from its range to [0, 1]; the particle spawns
//   dt * (trapped_air_rate * I_ta + crest_rate * I_wc) * I_speed
// on average per step, spread over its slots. Spawning runs every LIQUID_WHITEWATER_SPAWN_INTERVAL
// steps (SPAWN, the pass's second program), at that many steps' rate: the potentials read 3^d cells
// of two grids, which on a CPU rasterizer every fragment pays for whether it spawns or not.
// A secondary particle is spray where the density rho / rho0 is below spray_density (ballistic,
// with air drag), a bubble above bubble_density (buoyant, pulled toward the liquid's velocity),
// foam between (carried by the liquid's velocity). It is freed when its
// life is over or it enters an obstacle. The liquid never reads these textures.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_sample.glsl"

layout(set = 0, binding = LIQUID_BINDING_PARTICLE_POSITIONS) uniform sampler2D u_positions;   // the liquid's, end of step
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_VELOCITIES) uniform sampler2D u_velocities;
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_GRID_VELOCITY) uniform GRID_SAMPLER u_velocity;  // (u', fluid flag)
layout(set = 0, binding = LIQUID_BINDING_WHITEWATER_DENSITY) uniform GRID_SAMPLER u_density;      // rho / rho0, linear
layout(set = 0, binding = LIQUID_BINDING_WHITEWATER_POSITIONS) uniform sampler2D u_white_positions;    // xyz, kind
layout(set = 0, binding = LIQUID_BINDING_WHITEWATER_VELOCITIES) uniform sampler2D u_white_velocities;  // xyz, birth

layout(push_constant) uniform WhitewaterPushBlock {
  WhitewaterPush pc;
};

layout(location = 0) in vec2 v_uv;  // the full-screen vertex stage's (unused: gl_FragCoord is the slot)
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_velocity;

uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
float random01(uint seed) { return float(hash(seed) >> 8) * (1.0 / 16777216.0); }

float ramp(float value, float lo, float hi) { return clamp((value - lo) / (hi - lo), 0.0, 1.0); }

float density_at(vec3 x) { return sample_grid_linear(u_density, x).r; }

// The liquid's velocity at x, in one filtered fetch instead of the particle pass's eight: the linear
// interpolation of (u', fluid flag) over the cells around x, less the empty cells' share, which the
// grid pass accelerated from rest like any other cell (dt g), over the liquid cells' share. That is
// the particle pass's interpolation over the cells that hold liquid, except beside a brush or an
// obstacle, whose empty cells hold more than dt g: an error in the foam's path, never the liquid's.
vec3 liquid_velocity(vec3 x) {
  vec4 s = sample_grid_linear(u_velocity, x);
  if (s.a < 1e-3) return vec3(0.0);
  return (s.rgb - (1.0 - s.a) * u.dt * u.gravity) / s.a;
}

#if DIM == 3
const int k_span = 3;
#else
const int k_span = 1;
#endif

// The trapped-air and crest potentials of a liquid particle at x moving at v, from the 3^d cells
// around its own.
vec2 potentials(vec3 x, vec3 v) {
  float h = cell_size();
  ivec3 c = ivec3(floor(x / h));
#if DIM == 2
  c.z = 0;
#endif
  float rho[27];
  float approach = 0.0, weight = 0.0;
  for (int k = 0; k < k_span; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        ivec3 o = ivec3(i - 1, j - 1, DIM == 3 ? k - 1 : 0);
        rho[(k * 3 + j) * 3 + i] = fetch_grid(u_density, c + o).r;
        vec4 cell = fetch_grid(u_velocity, c + o);
        if (cell.a < 0.5 || o == ivec3(0)) continue;
        vec3 d = cell_center(c + o) - x;  // -x_pc
        vec3 relative = v - cell.rgb;     // v_pc
        float speed = length(relative);
        float w = max(0.0, 1.0 - dot(d, d) / (4.0 * h * h));
        w = w * w * w;
        if (speed > 0.0) approach += w * speed * (1.0 + dot(relative / speed, normalize(d)));
        weight += w;
      }
  float trapped_air = weight > 0.0 ? approach / weight : 0.0;

  // The density's gradient at the 2^d corners of the cell (each from the 2^d cells around it), the
  // outward normal there, and its divergence at the cell's centre.
  vec3 normals[8];
  vec3 gradient_sum = vec3(0.0);
  int corners = DIM == 3 ? 8 : 4;
  for (int n = 0; n < corners; ++n) {
    ivec3 s = ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);  // the corner between cells s - 1 and s
    vec3 g = vec3(0.0);
    for (int m = 0; m < corners; ++m) {
      ivec3 t = ivec3(m & 1, (m >> 1) & 1, (m >> 2) & 1);
      ivec3 cell = s + t;  // 0..2 per axis: s - 1 + t, shifted by one into the 3^d block
      float value = rho[((DIM == 3 ? cell.z : 0) * 3 + cell.y) * 3 + cell.x];
      g += value * (vec3(t) * 2.0 - 1.0);
    }
    g /= float(corners / 2) * h;
#if DIM == 2
    g.z = 0.0;
#endif
    gradient_sum += g;
    normals[n] = length(g) > 0.0 ? -g / length(g) : vec3(0.0);
  }
  vec3 divergence = vec3(0.0);  // d n_a / d x_a, from the corners' differences along a
  for (int n = 0; n < corners; ++n) {
    vec3 side = vec3(ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1)) * 2.0 - 1.0;
    divergence += side * normals[n];
  }
  float curvature = (divergence.x + divergence.y + divergence.z) / (float(corners / 2) * h);
  vec3 gradient = gradient_sum / float(corners);
  // Only on the surface (the density falls across it by at least a tenth per cell), moving out.
  float crest = 0.0;
  float speed = length(v);
  if (length(gradient) * h > 0.1 && speed > 0.0 && dot(v / speed, -normalize(gradient)) >= 0.6) crest = curvature;
  return vec2(trapped_air, crest);
}

// Kind by the density at x.
float kind_at(vec3 x) {
  float rho = density_at(x);
  return rho < pc.spray_density ? LIQUID_WHITEWATER_SPRAY : rho > pc.bubble_density ? LIQUID_WHITEWATER_BUBBLE
                                                                                     : LIQUID_WHITEWATER_FOAM;
}

bool inside_obstacle(vec3 x) {
  bool inside = false;
  MeshSample meshes = mesh_sample(x, false);
#define LIQUID_INSIDE(i) if (i < obstacle_count() && obstacle_distance(i, x, meshes) < 0.0) inside = true;
  FOR_EACH_OBSTACLE(LIQUID_INSIDE)
#undef LIQUID_INSIDE
  return inside;
}

void free_slot() {
  out_position = vec4(0.0);
  out_velocity = vec4(0.0);
}

// A free slot of the liquid particle at `owner` spawns with its share of the particle's rate.
void spawn(ivec2 owner, uint seed) {
  vec3 x_p = texelFetch(u_positions, owner, 0).xyz;
  vec3 v_p = texelFetch(u_velocities, owner, 0).xyz;
  float speed = ramp(length(v_p), pc.speed_lo, pc.speed_hi);
  if (speed <= 0.0) { free_slot(); return; }
  vec2 p = potentials(x_p, v_p);
  float rate = pc.trapped_air_rate * ramp(p.x, pc.trapped_air_lo, pc.trapped_air_hi) +
               pc.crest_rate * ramp(p.y, pc.crest_lo, pc.crest_hi);
  float expected = float(LIQUID_WHITEWATER_SPAWN_INTERVAL) * pc.dt * rate * speed / float(pc.slots);
  if (random01(seed) >= expected) { free_slot(); return; }
  // A random point within spawn_radius (a disc in 2D), moved on by a random part of the step.
  vec3 offset = vec3(random01(seed + 1U), random01(seed + 2U), random01(seed + 3U)) * 2.0 - 1.0;
#if DIM == 2
  offset.z = 0.0;
#endif
  offset = length(offset) > 1.0 ? offset / length(offset) * random01(seed + 4U) : offset;
  vec3 lo, hi;
  domain_bounds_from(x_p, lo, hi);
  vec3 x = clamp_to_bounds(x_p + pc.spawn_radius * offset + random01(seed + 5U) * pc.dt * v_p, lo, hi);
  if (inside_obstacle(x)) { free_slot(); return; }
  out_position = vec4(x, kind_at(x));
  out_velocity = vec4(v_p, pc.time);
}

#if SPAWN
#define SPAWN_OR_FREE(owner, seed) spawn(owner, seed)
#else
#define SPAWN_OR_FREE(owner, seed) free_slot()
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 owner = ivec2(texel.x, texel.y % pc.owner_rows);
  int owner_index = owner.y * u.particle_texture_width + owner.x;
  if (owner_index >= u.active_after) { free_slot(); return; }
  uint slot_id = uint(texel.y * u.particle_texture_width + texel.x);

  vec4 position = texelFetch(u_white_positions, texel, 0);
  vec4 velocity = texelFetch(u_white_velocities, texel, 0);
  if (position.w == LIQUID_WHITEWATER_FREE) {
    SPAWN_OR_FREE(owner, hash(slot_id * 4U + hash(uint(pc.step))) * 8U);
    return;
  }

  // Its life: `lifetime` times 0.5 to 1.5, fixed at its birth.
  float birth = velocity.w;
  float life = pc.lifetime * (0.5 + random01(slot_id ^ floatBitsToUint(birth)));
  if (pc.time - birth > life) { free_slot(); return; }

  float dt = pc.dt;
  vec3 x = position.xyz, v = velocity.xyz;
  vec3 lo, hi;
  domain_bounds_from(x, lo, hi);
  float kind = position.w;
  // The liquid's velocity is read once for foam and bubbles: a CPU rasterizer runs every branch.
  vec3 liquid = liquid_velocity(x);
  if (kind == LIQUID_WHITEWATER_SPRAY)
    v += dt * (u.gravity - pc.spray_drag * v);
  else if (kind == LIQUID_WHITEWATER_FOAM)
    v = liquid;
  else
    v += -pc.bubble_buoyancy * dt * u.gravity + min(1.0, pc.bubble_drag * dt) * (liquid - v);
  vec3 x_new = x + dt * v;
  x_new = clamp_to_bounds(x_new, lo, hi);
  for (int a = 0; a < DIM; ++a) {  // no velocity into a wall it was stopped at
    if (x_new[a] <= lo[a] && v[a] < 0.0) v[a] = 0.0;
    if (x_new[a] >= hi[a] && v[a] > 0.0) v[a] = 0.0;
  }
#if DIM == 2
  v.z = 0.0;
#endif
  if (inside_obstacle(x_new)) { free_slot(); return; }
  out_position = vec4(x_new, kind_at(x_new));
  out_velocity = vec4(v, birth);
}
