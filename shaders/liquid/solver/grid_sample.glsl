// The grid's velocity at a particle (section 5), for the particle pass (particle.frag).
// Include after common.glsl.
#ifndef LIQUID_GRID_SAMPLE_GLSL
#define LIQUID_GRID_SAMPLE_GLSL

// The cell centres around x for trilinear (bilinear in 2D) interpolation: the lowest one, base, and
// x's fraction f of the way to the next along each axis (z 0 in 2D); corner i is base + ivec3(i & 1,
// (i >> 1) & 1, (i >> 2) & 1) for i below k_grid_corners.
#if DIM == 3
const int k_grid_corners = 8;
#else
const int k_grid_corners = 4;
#endif
void grid_corners(vec3 x, out ivec3 base, out vec3 f) {
  vec3 g = x / cell_size() - 0.5;
  base = ivec3(floor(g));
  f = g - vec3(base);
#if DIM == 2
  f.z = 0.0;
  base.z = 0;
#endif
}

// Trilinear (bilinear in 2D) interpolation between cell centres over the cells that hold liquid,
// so empty cells (no splatted velocity) do not drag the particle: u' from `velocity` (u', fluid
// flag) and, with `with_splatted`, u from `splat` (sum w u, sum w).
void sample_grid(GRID_SAMPLER velocity, GRID_SAMPLER splat, vec3 x, bool with_splatted, out vec3 u_new, out vec3 u_old) {
  ivec3 base;
  vec3 f;
  grid_corners(x, base, f);
  u_new = vec3(0.0);
  u_old = vec3(0.0);
  float total = 0.0;
  for (int i = 0; i < k_grid_corners; ++i) {
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

#if AFFINE
// The affine transfer (APIC, Jiang et al. 2015) with the splat's own kernel: u' and u at the
// particle and u''s gradient C_p, from a weighted least-squares fit of a linear field
// u(x_p + d) = a + C d to the cells within the kernel's radius that hold liquid, weighted by the
// splat's w(d). Both transfers then use the same weights, as APIC needs: the splat extrapolates
// u_p + C_p d over that radius, and a gradient of the bilinear interpolant (two cells wide) carried
// three cells out amplified the grid's shortest waves until the liquid blew up. A fit, not a mean,
// so that a linear field comes back exactly also where the free surface cuts the kernel.
// Returns false (its outputs then unset) where too few cells hold liquid to fit.
bool fit_grid_affine(GRID_SAMPLER velocity, GRID_SAMPLER splat, vec3 x, out vec3 u_new, out mat3 c_new,
                     out vec3 u_old) {
  float r = u.kernel_radius;
  vec3 g = x / cell_size() - 0.5;  // in cells, cell centres at whole numbers
  ivec3 n = grid_cells();
  ivec3 lo = max(ivec3(ceil(g - r)), ivec3(0)), hi = min(ivec3(floor(g + r)), n - 1);
#if DIM == 2
  lo.z = 0;
  hi.z = 0;
  g.z = 0.0;
#endif
  mat4 normal = mat4(0.0);
  mat3x4 fit_new = mat3x4(0.0), fit_old = mat3x4(0.0);  // per velocity component, sum w u b
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int xi = lo.x; xi <= hi.x; ++xi) {
        vec3 d = vec3(xi, y, z) - g;
        float t = 1.0 - dot(d, d) / (r * r);
        if (t <= 0.0) continue;
        vec4 cell = fetch_grid(velocity, ivec3(xi, y, z));
        if (cell.a < 0.5) continue;  // no liquid in this cell
        vec4 s = fetch_grid(splat, ivec3(xi, y, z));
        float w = t * t * t;
        vec4 b = vec4(1.0, d);
        normal += w * outerProduct(b, b);
        fit_new += w * outerProduct(b, cell.rgb);
        fit_old += w * outerProduct(b, s.rgb / max(s.a, k_fluid_epsilon));
      }
#if DIM == 2
  normal[3][3] = 1.0;  // no z: its coefficient is zero
#endif
  if (abs(determinant(normal)) < 1e-6) return false;
  mat4 solve = inverse(normal);
  mat3x4 coefficients_new = solve * fit_new, coefficients_old = solve * fit_old;
  for (int j = 0; j < 3; ++j) {
    u_new[j] = coefficients_new[j][0];
    u_old[j] = coefficients_old[j][0];
    for (int a = 0; a < 3; ++a) c_new[a][j] = coefficients_new[j][a + 1] / cell_size();
  }
  return true;
}
#endif

#endif
