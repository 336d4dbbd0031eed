#version 450
// Particle pass (section 5): one fragment per particle texel, two render targets (position,
// velocity). Velocity by the PIC/FLIP blend
//   u_p' = r u'(x_p) + (1 - r) (u_p + u'(x_p) - u(x_p))
// where u is the splatted grid velocity and u' the grid pass's result; position by RK2 (midpoint)
// through u', clamped inside the domain at each stage:
//   x_mid = x_p + dt/2 u'(x_p),  x_p' = x_p + dt u'(x_mid)
// (the chapter's printed formula drops x_p from both lines). Texels past the active count are
// inactive (w = 0); texels in an emitter's range this step are spawned at its nozzle. Under the
// affine transfer (AFFINE) it also writes C_p, the gradient of u' at x_p. Under the pressure
// projection (PROJECTION) the particle then moves by its density correction, -grad psi.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_sample.glsl"

layout(set = 0, binding = LIQUID_BINDING_PARTICLE_POSITIONS) uniform sampler2D u_positions;
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_VELOCITIES) uniform sampler2D u_velocities;
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_SPLAT) uniform GRID_SAMPLER u_splat;             // (sum w u, sum w)
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_GRID_VELOCITY) uniform GRID_SAMPLER u_velocity;  // (u', fluid flag)
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_DEPOSIT) uniform GRID_SAMPLER u_deposit;  // (sum w_hat u, sum w_hat)
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_DEPOSIT_UPPER) uniform GRID_SAMPLER u_deposit_upper;
// A constant, not a branch on the uniform: with `if (u.position_correction > 0.0)` lavapipe (Mesa
// 22.3) grew by 1.5 MB a step, whatever the value (it specializes shaders on uniforms that branches read).
layout(constant_id = LIQUID_PARTICLE_POSITION_CORRECTION_ID) const bool POSITION_CORRECTION = false;
#ifndef PROJECTION
#define PROJECTION 0
#endif
#if PROJECTION
layout(set = 0, binding = LIQUID_BINDING_PARTICLE_CORRECTION) uniform GRID_SAMPLER u_correction;  // -grad psi
#endif

layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_velocity;
#if AFFINE
// C_p's columns d u / d x_a (1/s): 2D packed as (x column xy, y column xy); 3D one per axis.
layout(location = 2) out vec4 out_affine0;
#if DIM == 3
layout(location = 3) out vec4 out_affine1;
layout(location = 4) out vec4 out_affine2;
#endif
#endif

// The affine transfer's C_p of the new particle (zero for an inactive or new one); nothing without
// the affine transfer, whose variants' code is then the chapter's alone.
#if AFFINE
void write_affine(mat3 columns) {
#if DIM == 3
  out_affine0 = vec4(columns[0], 0.0);
  out_affine1 = vec4(columns[1], 0.0);
  out_affine2 = vec4(columns[2], 0.0);
#else
  out_affine0 = vec4(columns[0].xy, columns[1].xy);
#endif
}
#define WRITE_AFFINE(columns) write_affine(columns)
#else
#define WRITE_AFFINE(columns)
#endif

vec3 grid_velocity(vec3 x) {
  vec3 u_new, unused;
  sample_grid(u_velocity, u_splat, x, false, u_new, unused);
  return u_new;
}

// How far cell c's fine density (the deposit's, a kernel one cell wide) stands above what the splat's
// kernel reads there, or above rho0 where that reads less: particles packed closer than the wide
// kernel sees.
float fine_excess(ivec3 c) {
  c = clamp(c, ivec3(0), grid_cells() - 1);
  float weight = fetch_grid(u_deposit, c).a;
#if DIM == 3
  if (c.z > 0) weight += fetch_grid(u_deposit_upper, c - ivec3(0, 0, 1)).a;
#endif
  float fine = weight * u.deposit_density_scale;
  float coarse = fetch_grid(u_splat, c).a * u.density_scale / u.rest_density;
  return max(fine - max(coarse, 1.0), 0.0);
}

// A correction's step, at most a quarter cell long.
vec3 quarter_cell_at_most(vec3 step_) {
  float length_ = length(step_), most = 0.25 * cell_size();
  return length_ > most ? step_ * (most / length_) : step_;
}

// The position correction: down the gradient of the bilinear interpolant of fine_excess(), scaled
// by beta h^2, at most a quarter cell.
vec3 position_correction(vec3 x) {
  ivec3 base;
  vec3 f;
  grid_corners(x, base, f);
  vec3 gradient = vec3(0.0);
  for (int i = 0; i < k_grid_corners; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 t = mix(1.0 - f, f, vec3(o));
    vec3 sign_ = mix(vec3(-1.0), vec3(1.0), vec3(o));
    float e = fine_excess(base + o);
    gradient += e * vec3(sign_.x * t.y * t.z, t.x * sign_.y * t.z, t.x * t.y * sign_.z);
  }
#if DIM == 2
  gradient.z = 0.0;
#endif
  return quarter_cell_at_most(-u.position_correction * cell_size() * gradient);  // gradient is per cell
}

#if PROJECTION
// The projection's density correction at x (projection.glsl): the grid pass's -grad psi,
// interpolated like the velocity so that the particles' steps vary smoothly (the gradient of psi's
// own bilinear interpolant is constant within a cell and converges on its centres, where it gathered
// the particles into rows), at most a quarter cell.
vec3 density_correction(vec3 x) {
  ivec3 base;
  vec3 f;
  grid_corners(x, base, f);
  vec3 step_ = vec3(0.0);
  for (int i = 0; i < k_grid_corners; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 t = mix(1.0 - f, f, vec3(o));
    step_ += t.x * t.y * t.z * fetch_grid(u_correction, base + o).xyz;
  }
  return quarter_cell_at_most(step_);
}
#endif

uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
float random01(uint seed) { return float(hash(seed) >> 8) * (1.0 / 16777216.0); }

// A new particle of an emitter: a random point of the nozzle disc (segment in 2D), pushed a
// random fraction of one step along the jet so a step's particles do not stack in one plane.
void emit(int index, EmitterRange e) {
  vec3 axis = normalize(e.velocity);
  uint seed = uint(index) * 9781U + 12345U;
  float along = random01(seed + 1U) * length(e.velocity) * u.dt;
#if DIM == 3
  vec3 side = normalize(abs(axis.y) < 0.9 ? cross(axis, vec3(0, 1, 0)) : cross(axis, vec3(1, 0, 0)));
  vec3 up = cross(axis, side);
  float radius = e.radius * sqrt(random01(seed + 2U));
  float angle = 6.2831853 * random01(seed + 3U);
  vec3 offset = radius * (cos(angle) * side + sin(angle) * up);
#else
  vec3 side = vec3(-axis.y, axis.x, 0.0);
  vec3 offset = side * e.radius * (2.0 * random01(seed + 2U) - 1.0);
#endif
  out_position = vec4(clamp_to_domain(e.position + offset + axis * along), 1.0);
  out_velocity = vec4(e.velocity, 0.0);
  WRITE_AFFINE(mat3(0.0));
}

// Obstacle i: a particle at x inside it or within `skin` of it is moved back to that distance from
// its surface (kept in [lo, hi]) and loses its velocity v into it, relative to the obstacle's
// material there. Under the equation of state a dynamic body's only to a tenth of `skin`, keeping
// its velocity (main()): its force is the liquid's density over its kernel coverage, which a gap
// would read low; under the projection a body is solid as a static obstacle is (projection.glsl).
void push_out(int i, MeshSample meshes, float skin, vec3 lo, vec3 hi, inout vec3 x, inout vec3 v) {
  if (i >= obstacle_count()) return;
  float d = obstacle_distance(i, x, meshes);
  bool light_touch = obstacle_dynamic(i) && PROJECTION == 0;
  float reach = light_touch ? 0.1 * skin : skin;
  if (d >= reach) return;
  vec3 normal = obstacle_normal(i, x, meshes);
  x = clamp_to_bounds(x + (reach - d) * normal, lo, hi);
  if (light_touch) return;
  float into = dot(v - obstacle_velocity_at(i, x), normal);
  if (into < 0.0) v -= into * normal;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int index = texel.y * u.particle_texture_width + texel.x;
  if (index >= u.active_after) {  // inactive texel
    out_position = vec4(0.0);
    out_velocity = vec4(0.0);
    WRITE_AFFINE(mat3(0.0));
    return;
  }
  if (HAS_EMITTERS && index >= u.active_before) {  // emitted this step
    for (int i = 0; i < u.emission_count; ++i)
      if (index >= u.emitters[i].first && index < u.emitters[i].end) {
        emit(index, u.emitters[i]);
        return;
      }
    out_position = vec4(0.0);
    out_velocity = vec4(0.0);
    WRITE_AFFINE(mat3(0.0));
    return;
  }

  float dt = u.dt;
  float pic = u.pic_ratio;
  vec3 x = texelFetch(u_positions, texel, 0).xyz;
  vec3 v = texelFetch(u_velocities, texel, 0).xyz;

  // Section 5.1: PIC/FLIP blend.
  vec3 u_new, u_old;
#if AFFINE
  // The affine transfer: u', u and C_p from the fit with the splat's kernel (grid_sample.glsl),
  // C_p deposited with u_p by the next splat; the chapter's interpolation where too few cells
  // hold liquid to fit.
  mat3 c_new;
  if (!fit_grid_affine(u_velocity, u_splat, x, u_new, c_new, u_old)) {
    sample_grid(u_velocity, u_splat, x, true, u_new, u_old);
    c_new = mat3(0.0);
  }
  write_affine(c_new);
#else
  sample_grid(u_velocity, u_splat, x, true, u_new, u_old);
#endif
  v = pic * u_new + (1.0 - pic) * (v + u_new - u_old);

  // Section 5.2: RK2 (midpoint) through the updated grid, clamped inside the domain at each stage.
  vec3 lo, hi;
  domain_bounds_from(x, lo, hi);
  vec3 x_mid = clamp_to_bounds(x + 0.5 * dt * u_new, lo, hi);
  vec3 x_new = clamp_to_bounds(x + dt * grid_velocity(x_mid), lo, hi);
  if (POSITION_CORRECTION) x_new = clamp_to_bounds(x_new + position_correction(x), lo, hi);
#if PROJECTION
  x_new = clamp_to_bounds(x_new + density_correction(x), lo, hi);
#endif

  // Obstacles: a particle that ended inside (or within half a cell of) an obstacle is moved back
  // to its surface and loses its velocity into it, relative to the obstacle's material there.
  // A dynamic obstacle's particles are moved only, and only out of it (a twentieth of a cell
  // beyond its surface, not half a cell, which would leave a gap the body's buoyancy counts): a
  // velocity change here would be momentum the body's force does not count; the grid pass's
  // no-inflow condition removes it on the next step, where the body exchange pass counts it
  // (docs/physics.md, "Bodies that float").
  float skin = LIQUID_OBSTACLE_SKIN_CELLS * cell_size();
  [[unroll]] for (int pass = 0; pass < 2; ++pass) {
    MeshSample meshes = mesh_sample(x_new, true);
#define LIQUID_PUSH_OUT(i) push_out(i, meshes, skin, lo, hi, x_new, v);
    FOR_EACH_OBSTACLE(LIQUID_PUSH_OUT)
#undef LIQUID_PUSH_OUT
  }

  // Walls: no velocity into a wall the particle was clamped against.
  for (int a = 0; a < DIM; ++a) {
    if (x_new[a] <= lo[a] && v[a] < 0.0) v[a] = 0.0;
    if (x_new[a] >= hi[a] && v[a] > 0.0) v[a] = 0.0;
  }
#if DIM == 2
  v.z = 0.0;
#endif
  out_position = vec4(x_new, 1.0);
  out_velocity = vec4(v, 0.0);
}
