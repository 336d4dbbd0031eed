// The pressure projection (scene key "projection_iterations" > 0): what its passes share. The liquid
// fraction of a cell is the splat's density over rest density (with the walls' kernel coverage);
// cells at or above k_surface_fraction are liquid, the others air, where the pressure is zero. The
// free surface lies between a liquid cell and an air neighbour where the fraction crosses
// k_surface_fraction (linear), and the pressure's zero is placed there (the ghost-fluid method,
// Gibou et al. 2002). Include after common.glsl and pressure.glsl, with u_splat bound.
// The same Jacobi passes solve a second equation beside it, for the density correction (Kugelstadt
// et al. 2019, "Implicit density projection for volume conserving liquids"): lap psi = -rate (rho /
// rho0 - 1), psi = 0 on the surface, whose gradient moves the particles (particle.frag) by
// d = -grad psi, so that div d = rate (rho / rho0 - 1) spreads packed liquid and gathers sparse
// liquid. It moves positions only: the velocities are the projection's alone, so the correction
// adds no energy (a divergence target in the velocity did, and FLIP kept it: docs/physics.md).
#ifndef LIQUID_PROJECTION_GLSL
#define LIQUID_PROJECTION_GLSL

const float k_surface_fraction = 0.5;
// The nearest the surface may be taken to a liquid cell's centre, in cells: closer, the ghost
// pressure's weight 1/theta would let one noisy surface cell set its neighbours' pressure. Small:
// wherever the clamp holds, the pressure no longer follows the surface's height, and a wave whose
// height stays within it loses its restoring force there (at a quarter cell a 2D pulse of 0.3
// cells ran 11 to 20 % slow at 64 cells, and in 3D its first mode froze: docs/physics.md, "The
// surface's nearest distance").
const float k_min_surface_distance = 0.05;
// The share of a cell's density error the correction takes away per step: a fraction, so that the
// splat's sampling noise from one step to the next moves the particles little.
const float k_density_correction_rate = 0.2;
// Near the surface (air within the kernel's reach) only an excess above this share counts: the
// splat reads low there for the air, so a deficit says nothing, and a correction that spreads every
// small excess and gathers no deficit could only ever raise the surface. With it the pools keep
// their level (docs/physics.md, "The density correction", which also gives a run without it).
const float k_surface_excess_margin = 0.1;

// Solid obstacles: a cell whose centre lies inside one is solid, like a wall: its faces carry the
// obstacle's velocity (none through a still one) and it drops out of its liquid neighbours' rows
// (Neumann), so the liquid rests on it with its hydrostatic pressure instead of meeting a free
// surface there. The static obstacles are solid in every pass that includes this file; the dynamic
// bodies in the passes that read their state (LIQUID_BODIES: the row, grid and body force passes),
// so the liquid moves with a body and its pressure on it is the body's force (body_force.vert).
// The nearest solid obstacle at cell c's centre: its index (-1: none) and signed distance (m).
struct SolidObstacle {
  int index;
  float distance;
};
bool solid_to_projection(int i) {
#ifdef LIQUID_BODIES
  return i < obstacle_count();
#else
  return i < obstacle_count() && !obstacle_dynamic(i);
#endif
}
SolidObstacle nearest_solid_obstacle(ivec3 c) {
  SolidObstacle nearest = SolidObstacle(-1, LIQUID_MESH_FAR);
  if (obstacle_count() == 0) return nearest;
  vec3 p = cell_center(c);
  MeshSample meshes = mesh_sample_at_cell(c, false);
#define LIQUID_NEAREST_SOLID(i)                                     \
  if (solid_to_projection(i)) {                                     \
    float d = obstacle_distance(i, p, meshes);                      \
    if (d < nearest.distance) nearest = SolidObstacle(i, d);        \
  }
  FOR_EACH_OBSTACLE(LIQUID_NEAREST_SOLID)
#undef LIQUID_NEAREST_SOLID
  return nearest;
}

// The liquid beside a solid obstacle ends about a quarter cell past the particles' skin (half a
// spacing, a spacing being about half a cell), in cells from the obstacle's surface.
const float k_obstacle_liquid_edge_cells = LIQUID_OBSTACLE_SKIN_CELLS - 0.25;

// Of cell c whose splat is `splat` and nearest solid obstacle `o` (for a pass that has them
// already), and of cell c: over the kernel's share inside the domain less its share past the
// obstacle's liquid edge (the plane there: the body table's lattice share). 0 in a solid cell.
// A cell beside a wall whose centre lies within the particles' skin of a body (the row under a body
// that rests the skin above the floor: body.frag) holds the film of liquid the body rests on, liquid
// at rest density wherever particles reach it. Read from its splat it was partly air, with p = 0
// under one side of a box on the floor and the still water's pressure under the other: the box
// tipped over toward its bare side and tumbled (docs/physics.md, "Bodies under the projection").
bool film_under_body(ivec3 c, vec4 splat, SolidObstacle o) {
  if (o.index < 0 || !obstacle_dynamic(o.index) || o.distance >= LIQUID_OBSTACLE_SKIN_CELLS * cell_size()) return false;
  if (splat.a <= k_fluid_epsilon) return false;
  ivec3 n = grid_cells();
  bool beside_wall = false;
  [[unroll]] for (int a = 0; a < DIM; ++a) beside_wall = beside_wall || c[a] == 0 || c[a] == n[a] - 1;
  return beside_wall;
}

float liquid_fraction(ivec3 c, vec4 splat, SolidObstacle o) {
  float coverage = cell_coverage(c);
  if (o.distance < 0.0) return 0.0;
  if (film_under_body(c, splat, o)) return 1.0;
  if (o.index >= 0) {
    float share = share_past_plane(o.distance / cell_size() - k_obstacle_liquid_edge_cells);
    coverage = max(coverage - share, k_min_body_coverage);
  }
  return u.density_scale * splat.a / (coverage * u.rest_density);
}
// The row pass keeps each cell's fraction in its system's 4th channel (projection_divergence.frag),
// this in a solid cell.
const float k_solid_cell_fraction = -1.0;

float liquid_fraction(ivec3 c, vec4 splat) { return liquid_fraction(c, splat, nearest_solid_obstacle(c)); }
float liquid_fraction(ivec3 c) { return liquid_fraction(c, fetch_grid(u_splat, c)); }

// The distance, in cells, from the centre of liquid cell c (fraction fc) to the surface toward its
// air neighbour (fraction fq < k_surface_fraction).
float surface_distance(float fc, float fq) {
  return max((fc - k_surface_fraction) / max(fc - fq, 1e-6), k_min_surface_distance);
}

#endif
