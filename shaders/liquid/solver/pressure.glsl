// The pressure of the grid pass (section 2.1) and the walls' kernel coverage, shared by grid.frag
// and by the splat-adjoint pressure passes (pressure.frag, potential.frag). Include after
// common.glsl.
#ifndef LIQUID_PRESSURE_GLSL
#define LIQUID_PRESSURE_GLSL

// Fraction of the kernel's mass beyond a wall k + 0.5 cells from a cell centre (k >= 0), from the
// table the setup computes once (liquid/physics/wall_coverage.h; r is at most LIQUID_MAX_KERNEL_RADIUS_CELLS).
// Selected with comparisons, not an indexed read: an index that differs between fragments is a
// gather on lavapipe.
float kernel_mass_beyond(int k) {
  float beyond = 0.0;
  [[unroll]] for (int i = 0; i < LIQUID_WALL_TABLE_SIZE; ++i)
    beyond = k == i ? u.wall_kernel_beyond[i / 4][i % 4] : beyond;
  return beyond;
}

// The kernel's share beyond a dynamic body's surface (the body table) `distance` cells from a cell
// centre (any distance >= 0): linear between the table's half-cell points, from one half on it.
float body_mass_beyond_entry(int k) {
  float beyond = 0.0;
  [[unroll]] for (int i = 0; i < LIQUID_WALL_TABLE_SIZE; ++i)
    beyond = k == i ? u.body_kernel_beyond[i / 4][i % 4] : beyond;
  return beyond;
}
float body_mass_beyond(float distance) {
  if (distance < 0.5) return mix(0.5, body_mass_beyond_entry(0), 2.0 * distance);
  int k = int(floor(distance - 0.5));
  return mix(body_mass_beyond_entry(k), body_mass_beyond_entry(k + 1), distance - 0.5 - float(k));
}

// Share of the kernel inside the domain along one axis, for the cell at index i of n: near a wall
// the kernel is cut off and the splatted density reads low, which would pull liquid against the
// wall; dividing by the share removes that bias. It is 1 from r cells away from both walls.
float axis_coverage(int i, int n) {
  i = clamp(i, 0, n - 1);
  return (1.0 - kernel_mass_beyond(i)) * (1.0 - kernel_mass_beyond(n - 1 - i));
}

// Share of the kernel at p outside the dynamic bodies, each taken as the plane through its nearest
// surface point (1 in shaders without LIQUID_BODIES): the liquid beside a body lacks the body's
// share of its kernel, as beside a wall, and without dividing by this it reads low, at zero
// pressure under the clamp, so the layer under a body could hold it anywhere (docs/physics.md,
// "Bodies that float"). Clamped: deep inside a body the kernel reaches only a few particles.
const float k_min_body_coverage = 0.05;
float body_coverage(vec3 p) {
  float coverage = 1.0;
#ifdef LIQUID_BODIES
#define LIQUID_BODY_FACTOR(i)                                                 \
  if (i < obstacle_count() && obstacle_dynamic(i)) {                          \
    float d = obstacle_distance(i, p) / cell_size();                          \
    coverage *= d >= 0.0 ? 1.0 - body_mass_beyond(d) : body_mass_beyond(-d); \
  }
  FOR_EACH_OBSTACLE(LIQUID_BODY_FACTOR)
#undef LIQUID_BODY_FACTOR
#endif
  return max(coverage, k_min_body_coverage);
}

// Liquid (default): Becker and Teschner's Tait form, which the chapter cites, clamped at zero:
// P = max(k ((rho/rho0)^gamma - 1), 0). Its gradient equals the printed P = k (rho/rho0)^gamma's
// wherever rho > rho0, but below rest density (the free surface, empty cells) it exerts no pull
// and no push, so the surface stays sharp instead of boiling off. Shallow water uses the printed
// form (with gamma = 1 it is the SWE's P = g (h + b)).
float pressure_from_density(float rho) {
  float ratio_pow = density_ratio_power(max(rho / u.rest_density, 0.0));
  return shallow_water() ? u.stiffness * ratio_pow : u.stiffness * max(ratio_pow - 1.0, 0.0);
}

// Share of the kernel inside the domain at cell c: the product of the axes' shares.
float cell_coverage(ivec3 c) {
  ivec3 n = grid_cells();
  float coverage = 1.0;
  [[unroll]] for (int a = 0; a < DIM; ++a) coverage *= axis_coverage(c[a], n[a]);
  return coverage;
}

#endif
