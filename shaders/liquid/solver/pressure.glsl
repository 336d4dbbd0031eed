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
  if (WALLS_CONTINUED) return 0.0;
  float beyond = 0.0;
  [[unroll]] for (int i = 0; i < LIQUID_WALL_TABLE_SIZE; ++i)
    beyond = k == i ? u.wall_kernel_beyond[i / 4][i % 4] : beyond;
  return beyond;
}

// The kernel's share beyond a dynamic body's surface (the body table) `distance` cells from a cell
// centre (any distance >= 0): linear between the table's half-cell points, from one half on it.
// Both entries are selected in one pass over the table.
float body_mass_beyond(float distance) {
  int k = int(floor(distance - 0.5));  // -1 below the first point; past the table both are 0
  float below = 0.0, above = 0.0;
  [[unroll]] for (int i = 0; i < LIQUID_WALL_TABLE_SIZE; ++i) {
    float entry = u.body_kernel_beyond[i / 4][i % 4];
    below = k == i ? entry : below;
    above = k + 1 == i ? entry : above;
  }
  return k < 0 ? mix(0.5, above, 2.0 * distance) : mix(below, above, distance - 0.5 - float(k));
}

// Share of the kernel inside the domain along one axis, for the cell at index i of n: near a wall
// the kernel is cut off and the splatted density reads low, which would pull liquid against the
// wall; dividing by the share removes that bias. It is 1 from r cells away from both walls.
float axis_coverage(int i, int n) {
  i = clamp(i, 0, n - 1);
  return (1.0 - kernel_mass_beyond(i)) * (1.0 - kernel_mass_beyond(n - 1 - i));
}

// The kernel's share beyond a plane `t` cells from its centre (t < 0: the centre is past the plane),
// from the body table.
float share_past_plane(float t) {
  float beyond = body_mass_beyond(abs(t));
  return t >= 0.0 ? beyond : 1.0 - beyond;
}

// The kernel's share at p inside dynamic obstacle i. A box's is the product of its slabs' shares
// along its own axes (each slab: 1 minus the shares past its two faces), exact for one face and
// right near its edges and corners, where a plane through the nearest surface point counts the
// kernel past the face's plane beyond the box (outside) or misses the second face (inside); a
// sphere's is the plane's (docs/physics.md, "Bodies that float").
float body_share_at(int i, vec3 p) {
  float h = cell_size();
  if (obstacle_kind(i) != LIQUID_OBSTACLE_BOX) return share_past_plane(obstacle_distance(i, p) / h);
  vec3 local = quat_rotate_inverse(obstacle_frame(i).orientation, obstacle_offset(i, p)) / h;
  vec3 e = u.obstacles[i].box_half_extent / h;
  float share = 1.0;
  [[unroll]] for (int a = 0; a < DIM; ++a)
    share *= max(1.0 - share_past_plane(e[a] - local[a]) - share_past_plane(e[a] + local[a]), 0.0);
  return share;
}

// Image `k` of p: p itself (k = 0), or its mirror image in the nearer wall of axis k - 1. Where the
// walls are the liquid continued through them (the separable splat folds the particles' images in),
// the liquid a cell's kernel reaches also lacks the images of a body near a wall.
const int k_body_images = 1 + DIM;
vec3 body_image(vec3 p, int k) {
  if (k == 0) return p;
  int a = k - 1;
  p[a] = p[a] < 0.5 * u.domain[a] ? -p[a] : 2.0 * u.domain[a] - p[a];
  return p;
}
int body_image_count() { return u.body_images_beyond_walls != 0 ? k_body_images : 1; }

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

// Share of the kernel at cell c the liquid may fill: inside the domain (the walls' share,
// cell_coverage) less the dynamic bodies' shares and their images' (none in shaders without
// LIQUID_BODIES: then exactly cell_coverage). The liquid beside a body lacks the body's share of its
// kernel, as beside a wall, and without dividing by this it reads low, at zero pressure under the
// clamp, so the layer under a body could hold it anywhere. The shares are subtracted, not
// multiplied: the kernel's parts in a body, in its images and past a wall do not overlap (a product
// counts their overlap back in, so the layer between a body and the floor read light). Clamped:
// deep inside a body the kernel reaches only a few particles (docs/physics.md, "Bodies that float").
const float k_min_body_coverage = 0.05;
float liquid_coverage(ivec3 c) {
  float walls = cell_coverage(c);
  float bodies = 0.0;
#ifdef LIQUID_BODIES
  vec3 p = cell_center(c);
#define LIQUID_BODY_SHARE(i)                                                          \
  if (i < obstacle_count() && obstacle_dynamic(i))                                    \
    for (int k = 0; k < body_image_count(); ++k) bodies += body_share_at(i, body_image(p, k));
  FOR_EACH_OBSTACLE(LIQUID_BODY_SHARE)
#undef LIQUID_BODY_SHARE
#endif
  return bodies > 0.0 ? max(walls - bodies, k_min_body_coverage) : walls;
}

#endif
