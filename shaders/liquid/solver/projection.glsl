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
// pressure's weight 1/theta would let one noisy surface cell set its neighbours' pressure.
const float k_min_surface_distance = 0.25;
// The share of a cell's density error the correction takes away per step: a fraction, so that the
// splat's sampling noise from one step to the next moves the particles little.
const float k_density_correction_rate = 0.2;
// Near the surface (air within the kernel's reach) only an excess above this share counts: the
// splat reads low there for the air, so a deficit says nothing, and a correction that spreads every
// small excess and gathers no deficit could only ever raise the surface. With it the pools keep
// their level (docs/physics.md, "The density correction", which also gives a run without it).
const float k_surface_excess_margin = 0.1;

// Of cell c whose splat is `splat` (for a pass that has read it already), and of cell c.
float liquid_fraction(ivec3 c, vec4 splat) {
  return u.density_scale * splat.a / (cell_coverage(c) * u.rest_density);
}
float liquid_fraction(ivec3 c) { return liquid_fraction(c, fetch_grid(u_splat, c)); }

// The distance, in cells, from the centre of liquid cell c (fraction fc) to the surface toward its
// air neighbour (fraction fq < k_surface_fraction).
float surface_distance(float fc, float fq) {
  return max((fc - k_surface_fraction) / max(fc - fq, 1e-6), k_min_surface_distance);
}

#endif
