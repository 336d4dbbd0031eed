// The grid pass's update of one cell (section 4, grid.frag), with the no-inflow condition the body
// exchange pass (body_exchange.vert) also applies. Include after common.glsl; SPLAT_ADJOINT as in
// grid.frag.
#ifndef LIQUID_GRID_UPDATE_GLSL
#define LIQUID_GRID_UPDATE_GLSL
#include "liquid/solver/pressure.glsl"

#ifndef SPLAT_ADJOINT
#define SPLAT_ADJOINT 0
#endif
#ifndef PROJECTION
#define PROJECTION 0
#endif

layout(set = 0, binding = LIQUID_BINDING_GRID_SPLAT) uniform GRID_SAMPLER u_splat;
#if SPLAT_ADJOINT || PROJECTION  // the projection's p in the potential's place
layout(set = 0, binding = LIQUID_BINDING_GRID_POTENTIAL) uniform GRID_SAMPLER u_potential;
#endif

// The chapter's pressure at neighbour cell c (clamped into the grid, which makes the difference
// one-sided at the walls: neighbour()) whose kernel share inside the domain is `coverage` and where
// the meshes' distances are `meshes`: liquid plus obstacle or ground density. (Dynamic bodies need
// the splat-adjoint pressure, whose P is pressure.frag's.)
float pressure_at(ivec3 c, float coverage, vec4 meshes) {
  float rho = u.density_scale * fetch_grid(u_splat, c).a / coverage;
  rho += obstacle_density_at_cell(c, meshes);
  if (shallow_water()) rho += u.rest_density * ground_height(cell_center(c).xy) / u.rest_depth;
  return pressure_from_density(rho);
}

// The neighbour `offset` cells from c, clamped into the grid.
ivec3 neighbour(ivec3 c, ivec3 offset) { return clamp(c + offset, ivec3(0), grid_cells() - 1); }

#if SPLAT_ADJOINT
// Phi at the neighbour `offset` (-1 or 1) cells from c along axis a; one cell beyond a wall, the
// wall cell's (fetch_grid clamps to its mirror image) plus the hydrostatic rise, as potential.frag
// gathers P. Only axis a can leave the grid, so only its part of the rise is taken.
float potential_at(ivec3 c, int a, int offset) {
  c[a] += offset;
  return fetch_grid(u_potential, c).r + wall_ghost_rise_along(a, c[a]);
}
#endif

#if PROJECTION
#include "liquid/solver/projection.glsl"
layout(set = 0, binding = LIQUID_BINDING_GRID_PROJECTION_SYSTEM) uniform GRID_SAMPLER u_projection_system;

// Cell c's liquid fraction as the row pass found it (k_solid_cell_fraction in a solid cell): one read
// instead of the splat, the walls' coverage and the obstacles again at every neighbour.
float stored_fraction(ivec3 c) { return fetch_grid(u_projection_system, c).w; }

// Twice the projection's gradients of p and psi (in cells, central differences: the mean of the two
// faces') at cell c, whose (p, psi) is sc and row (the row pass's system) `row`.
// In a liquid cell the differences take each neighbour q's (p, psi), or where q is not liquid its
// stand-in: beyond a wall p's hydrostatic ghost and psi's own (no flow through it); in a solid cell
// c's continued as still water's, p + g.n h both ways (under an overhang too, where the liquid presses
// against it from below); across the free surface the ghost-fluid values that put p = psi = 0 on the
// surface (projection_jacobi.frag).
// In an air cell that borders the liquid along an axis, p falls across the surface from a liquid
// neighbour's to 0 over the distance theta, so dp/dx = side p_q / theta (the mean of both sides where
// both are liquid); psi's gradient is 0 there. Without it the surface cell keeps only g dt, and the
// top particles, whose velocity blends it with the liquid cell below, sink into the layer under them.
// Cost, under lavapipe: every neighbour is read once, with no branch per neighbour (a fragment group
// that straddles the surface ran both sides of one), and its fraction only where it can matter. A
// liquid cell's neighbours are all liquid where its diagonal counts exactly its neighbours inside the
// grid and none of their p is 0 (the Jacobi passes leave 0 in air and solid cells; the count alone
// would miss a solid neighbour, which adds nothing, beside an air one whose 1 / theta is exactly 2),
// and an air cell whose neighbours' p are all 0 has a zero gradient whatever they are. The fractions
// were half the pass's reads.
void projection_gradients(ivec3 c, vec2 sc, vec4 row, out vec3 grad_p, out vec3 grad_psi) {
  ivec3 n = grid_cells();
  float fc = max(row.w, 0.0);  // a solid cell's is 0, as liquid_fraction() gives
  bool liquid = fc >= k_surface_fraction;
  vec2 neighbour[2 * DIM];  // (p, psi) at the lower [2 a] and upper [2 a + 1] neighbour along axis a
  float inside = 0.0;      // the neighbours inside the grid
  bool any_pressure = false, any_zero = false;
  [[unroll]] for (int k = 0; k < 2 * DIM; ++k) {
    ivec3 q = c;
    q[k / 2] += k % 2 == 0 ? -1 : 1;
    neighbour[k] = fetch_grid(u_potential, q).rg;  // fetch_grid clamps q into the grid
    bool in_grid = q[k / 2] >= 0 && q[k / 2] < n[k / 2];
    inside += in_grid ? 1.0 : 0.0;
    any_pressure = any_pressure || (in_grid && neighbour[k].x != 0.0);
    any_zero = any_zero || (in_grid && neighbour[k].x == 0.0);
  }
  float fraction[2 * DIM];
  bool mixed = liquid ? row.y != inside || any_zero : any_pressure;
  [[unroll]] for (int k = 0; k < 2 * DIM; ++k) fraction[k] = 1.0;  // liquid
  if (mixed) {
    [[unroll]] for (int k = 0; k < 2 * DIM; ++k) {
      ivec3 q = c;
      q[k / 2] += k % 2 == 0 ? -1 : 1;
      fraction[k] = stored_fraction(q);
    }
  }
  grad_p = grad_psi = vec3(0.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    vec2 difference = vec2(0.0);
    float air_sum = 0.0, air_sides = 0.0;
    [[unroll]] for (int side = -1; side <= 1; side += 2) {
      int k = 2 * a + (side + 1) / 2;
      int qa = c[a] + side;
      bool wall = qa < 0 || qa >= n[a];
      float fq = fraction[k];
      vec2 sq = neighbour[k];
      bool solid = fq == k_solid_cell_fraction, liquid_q = fq >= k_surface_fraction;
      vec2 value = wall ? vec2(sc.x + wall_ghost_rise_along(a, qa), sc.y)
                 : solid ? vec2(sc.x + float(side) * u.gravity[a] * cell_size(), sc.y)
                 : liquid_q ? sq : sc * (1.0 - 1.0 / surface_distance(fc, fq));
      difference += float(side) * value;
      bool beside_liquid = !wall && liquid_q;
      air_sum += beside_liquid ? float(side) * sq.x / surface_distance(fq, fc) : 0.0;
      air_sides += beside_liquid ? 1.0 : 0.0;
    }
    grad_p[a] = liquid ? difference.x : (air_sides > 0.0 ? 2.0 * air_sum / air_sides : 0.0);
    grad_psi[a] = liquid ? difference.y : 0.0;
  }
}
#endif

// Obstacle i's condition on the velocity at cell centre p: inside a static obstacle the liquid moves
// with it; inside a dynamic one and within a cell of any surface, no relative velocity into it (a
// body's force has no viscous part, so its inside may not drag the liquid along either:
// docs/physics.md, "Bodies that float"). The obstacle's velocity is its material's at p (v + w x r).
vec3 obstacle_condition(int i, vec3 p, vec3 velocity, MeshSample meshes) {
  float d = obstacle_distance(i, p, meshes);
  if (d > cell_size()) return velocity;
  vec3 v_obstacle = obstacle_velocity_at(i, p);
  if (d < 0.0 && !obstacle_dynamic(i)) return v_obstacle;
  vec3 normal = obstacle_normal(i, p, meshes);
  float into = dot(velocity - v_obstacle, normal);
  return into < 0.0 ? velocity - into * normal : velocity;
}

// u' of cell c whose splat is `splat`: the splatted velocity, accelerated by -grad P + g + f_ext
// over dt, then no flow through the walls or into obstacles. Under the pressure projection also
// `correction`, the density correction's step -grad psi (m) in a liquid cell (0 elsewhere, and
// without the projection).
vec3 grid_update(ivec3 c, vec4 splat, out vec3 correction) {
  ivec3 n = grid_cells();
  float h = cell_size();
  float dt = u.dt;
  bool fluid = splat.a > k_fluid_epsilon;
  vec3 velocity = fluid ? splat.rgb / splat.a : vec3(0.0);

#if PROJECTION
  // Central differences of the projection's p and psi: the mean of the two faces' gradients.
  vec3 grad_p, grad_psi;
  projection_gradients(c, fetch_grid(u_potential, c).rg, fetch_grid(u_projection_system, c), grad_p, grad_psi);
  correction = -grad_psi / (2.0 * h);
  MeshSample meshes = mesh_sample_at_cell(c, true);
#elif SPLAT_ADJOINT
  correction = vec3(0.0);
  // Central differences of Phi, with the hydrostatic ghost cells beyond the walls.
  vec3 grad_p = vec3(0.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) grad_p[a] = potential_at(c, a, 1) - potential_at(c, a, -1);
  MeshSample meshes = mesh_sample_at_cell(c, true);
#else
  correction = vec3(0.0);
  // Wall coverage is a product over the axes, so each neighbour's is the centre's with one factor
  // swapped: 3 factors per axis instead of a full product per neighbour.
  vec3 below = vec3(1.0), here = vec3(1.0), above = vec3(1.0);
  [[unroll]] for (int a = 0; a < DIM; ++a) {
    below[a] = axis_coverage(c[a] - 1, n[a]);
    here[a] = axis_coverage(c[a], n[a]);
    above[a] = axis_coverage(c[a] + 1, n[a]);
  }

  // The meshes' distances at the six neighbours, read once for their pressures and the cell's
  // normal (obstacle_condition).
  ivec3 x_above = neighbour(c, ivec3(1, 0, 0)), x_below = neighbour(c, ivec3(-1, 0, 0));
  ivec3 y_above = neighbour(c, ivec3(0, 1, 0)), y_below = neighbour(c, ivec3(0, -1, 0));
  ivec3 z_above = neighbour(c, ivec3(0, 0, 1)), z_below = neighbour(c, ivec3(0, 0, -1));
  vec4 meshes_x_above = mesh_distances_at_cell(x_above), meshes_x_below = mesh_distances_at_cell(x_below);
  vec4 meshes_y_above = mesh_distances_at_cell(y_above), meshes_y_below = mesh_distances_at_cell(y_below);
  MeshSample meshes = mesh_sample_of(mesh_distances_at_cell(c));
  meshes.gradient_x = meshes_x_above - meshes_x_below;
  meshes.gradient_y = meshes_y_above - meshes_y_below;

  // Eq. 3: central differences of the pressure.
  vec3 grad_p;
  grad_p.x = pressure_at(x_above, above.x * here.y * here.z, meshes_x_above) -
             pressure_at(x_below, below.x * here.y * here.z, meshes_x_below);
  grad_p.y = pressure_at(y_above, here.x * above.y * here.z, meshes_y_above) -
             pressure_at(y_below, here.x * below.y * here.z, meshes_y_below);
  grad_p.z = 0.0;
#if DIM == 3
  vec4 meshes_z_above = mesh_distances_at_cell(z_above), meshes_z_below = mesh_distances_at_cell(z_below);
  meshes.gradient_z = meshes_z_above - meshes_z_below;
  grad_p.z = pressure_at(z_above, here.x * here.y * above.z, meshes_z_above) -
             pressure_at(z_below, here.x * here.y * below.z, meshes_z_below);
#endif
#endif
  grad_p /= 2.0 * h;

  vec3 p = cell_center(c);
  vec3 acceleration = -grad_p + u.gravity + external_acceleration(p);
  velocity += dt * acceleration;

#define LIQUID_OBSTACLE_CONDITION(i) \
  if (i < obstacle_count()) velocity = obstacle_condition(i, p, velocity, meshes);
  FOR_EACH_OBSTACLE(LIQUID_OBSTACLE_CONDITION)
#undef LIQUID_OBSTACLE_CONDITION

  // Section 4's wall condition: in a cell next to a wall, the velocity component normal to that
  // wall is zero.
  if ((c.x == 0 && velocity.x < 0.0) || (c.x == n.x - 1 && velocity.x > 0.0)) velocity.x = 0.0;
  if ((c.y == 0 && velocity.y < 0.0) || (c.y == n.y - 1 && velocity.y > 0.0)) velocity.y = 0.0;
#if DIM == 3
  if ((c.z == 0 && velocity.z < 0.0) || (c.z == n.z - 1 && velocity.z > 0.0)) velocity.z = 0.0;
#else
  velocity.z = 0.0;
#endif
  return velocity;
}
vec3 grid_update(ivec3 c, vec4 splat) {
  vec3 unused;
  return grid_update(c, splat, unused);
}

#endif
