// The grid's velocity at a particle (section 5), for the particle pass (particle.frag).
// Include after common.glsl.
#ifndef LIQUID_GRID_SAMPLE_GLSL
#define LIQUID_GRID_SAMPLE_GLSL

// Trilinear (bilinear in 2D) interpolation between cell centres over the cells that hold liquid,
// so empty cells (no splatted velocity) do not drag the particle: u' from `velocity` (u', fluid
// flag) and, with `with_splatted`, u from `splat` (sum w u, sum w).
void sample_grid(GRID_SAMPLER velocity, GRID_SAMPLER splat, vec3 x, bool with_splatted, out vec3 u_new, out vec3 u_old) {
  vec3 g = x / cell_size() - 0.5;
  ivec3 base = ivec3(floor(g));
  vec3 f = g - vec3(base);
  u_new = vec3(0.0);
  u_old = vec3(0.0);
  float total = 0.0;
#if DIM == 3
  const int corners = 8;
#else
  const int corners = 4;
  f.z = 0.0;
  base.z = 0;
#endif
  for (int i = 0; i < corners; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 t = mix(1.0 - f, f, vec3(o));
    float weight = t.x * t.y * t.z;
    if (weight <= 0.0) continue;
    vec4 cell = fetch_grid(velocity, base + o);
    if (cell.a < 0.5) continue;  // no liquid in this cell
    total += weight;
    u_new += weight * cell.rgb;
    if (with_splatted) {
      vec4 s = fetch_grid(splat, base + o);
      u_old += weight * s.rgb / max(s.a, k_fluid_epsilon);
    }
  }
  if (total > 0.0) {
    u_new /= total;
    u_old /= total;
  }
}

#endif
