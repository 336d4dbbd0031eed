// Everything the solver derives from a scene before the first step: grid size and cell size,
// particle mass, rest density, the kernel normalisation, the particle texture size and the
// initial particles. Pure CPU code, so it is unit-tested without a device.
#pragma once

#include "liquid/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace liquid {

// What the device allows; checked here so a scene past the limits fails with a clear message.
struct DeviceLimits {
  int max_image_dimension_2d = 16384;
  int max_image_dimension_3d = 2048;
  int max_framebuffer_layers = 2048;
};

// The solver's parameters, derived from a scene once. The solver reads its scalars from here, never
// from the Scene (which keeps what the user wrote: shallow water, for one, replaces the scene's
// stiffness, gamma and gravity); only the scene's lists (obstacles, emitters, hills) are read there.
// A dynamic obstacle's rigid-body constants (liquid/physics/body.h), computed once: a mesh's take
// passes over its triangles.
struct BodyConstants {
  float mass = 0.0f;                 // kg
  glm::vec3 inertia{0.0f};           // kg m^2, about the body's axes
  float added_mass = 0.0f;           // kg (body_added_mass)
  float added_inertia_ratio = 0.0f;  // (body_added_inertia_ratio)
  // A dynamic mesh's: its distance texture's half side (body_shape_half_size) and its vertices'
  // largest |coordinate| per axis about its centre of mass (m; the wall contact's extent).
  float shape_half_size = 0.0f;
  glm::vec3 shape_half_extent{0.0f};
};

struct SimulationSetup {
  int dimension = 2;
  bool shallow_water = false;   // section 6's height-field mode
  glm::ivec3 grid_cells{1};     // cells per axis (z = 1 in 2D)
  float cell_size = 0.0f;       // m, h: cells are square/cubic
  glm::vec3 domain{0.0f};       // m, grid_cells * cell_size (the scene's box, snapped to whole cells)
  float time_step = 0.0f;       // s
  float particle_spacing = 0.0f;  // m
  float particle_mass = 0.0f;   // kg, density * spacing^d
  float rest_density = 0.0f;    // kg/m^3, rho0
  // rho = density_scale * sum_p w(d, r): the chapter's rho = m sum w, divided by the kernel's
  // integral (in m^d) so that a uniform lattice of the liquid's density reads that density.
  float density_scale = 0.0f;   // kg/m^3 per unit of summed weight
  float stiffness = 0.0f;       // k (shallow water: g * rest_depth)
  float gamma = 0.0f;           // the scene's (shallow water: 1)
  glm::vec3 gravity{0.0f};      // m/s^2 (shallow water: zero in the plane)
  float kernel_radius_cells = 0.0f;  // r, the splat radius in cells (the scene's)
  float pic_ratio = 0.0f;       // section 5.1's blend: 1 = PIC, 0 = FLIP (the scene's)
  float pic_ratio_reference_step = 0.0f;  // s, the step pic_ratio is given for; 0: per step (the chapter's)
  bool splat_adjoint_pressure = false;  // the scene's pressure_force is splat_adjoint
  SplatMode splat = SplatMode::PointSprite;  // the scene's splat
  bool long_steps = false;      // long_step_regime(scene): sets the acoustic CFL (physics/time_step.h)
  float wall_margin = 0.0f;     // m, particles are kept this far from every wall (or where they started, if closer)
  std::vector<float> wall_share_beyond;  // the kernel's share beyond a wall k + 0.5 cells away (wall_coverage.h)
  std::vector<float> body_share_beyond;  // the same beyond a dynamic body's surface (body_share_beyond)
  std::vector<BodyConstants> bodies;     // per obstacle: a dynamic one's constants (zero for the others)
  float obstacle_band = 0.0f;   // m, the obstacle density falls to zero this far outside (one kernel radius)
  float rest_depth = 0.0f;      // m, shallow water's depth at rest
  int initial_particles = 0;    // from fluid blocks
  int capacity = 0;             // initial + all emitters' capacities
  glm::ivec2 particle_texture{1};  // W x H texels, W * H >= capacity
  std::vector<glm::vec4> positions;   // initial particles: xyz in m, w = 1 (active)
  std::vector<glm::vec4> velocities;  // initial particles: xyz in m/s, w = 0
};

// The axis gravity lies along, or -1 where it has no component or more than one (still water's
// pressure then has no single column direction).
int single_gravity_axis(int dimension, glm::vec3 gravity);

// Integral of w(d, r) = (1 - d^2/r^2)^3 over the plane (d = 2) or space (d = 3), r in cells:
// pi r^2 / 4 in 2D, 64 pi r^3 / 315 in 3D.
double kernel_integral_cells(int dimension, double radius_cells);

// The integral of the scene's splat kernel (liquid/physics/kernel.h), cells^d: the radial one's
// above, or the separable one's (sum_j b_j)^d, since each axis's profile interpolates its taps.
double splat_kernel_integral_cells(SplatMode mode, int dimension, double radius_cells);

// A scene without grid_resolution gets cells of this many particle spacings, as the shipped physical
// scenes are built (1.5 to 2.5): the liquid, not the domain, sets the resolution. (round(N^(1/d))
// over the whole domain gave a column in a wide tank 5.7 spacings a cell, and a surge front 9.4 %
// behind Martin & Moyce where two spacings give 7.7 %.)
inline constexpr double k_default_spacings_per_cell = 2.0;

// The cells along the longest axis: grid_resolution, or the longest side over
// k_default_spacings_per_cell spacings (at least k_min_grid_cells).
int longest_axis_cells(const Scene& scene);
inline constexpr int k_min_grid_cells = 8;

// The longest of a domain's first `dimension` sides, m (a scene's as written, or a setup's snapped
// to whole cells).
double longest_side(glm::vec3 domain, int dimension);

// The cell size h the setup gives the scene, m: the longest side over longest_axis_cells.
double scene_cell_size(const Scene& scene);

// k and gamma of the scene's pressure law (shallow water: P = g h, k = |g| rest_depth, gamma = 1).
struct PressureLaw {
  float stiffness = 0.0f;
  float gamma = 1.0f;
};
PressureLaw pressure_law(const Scene& scene);

// Derives the setup; throws SceneError naming the scene and the problem (a grid or particle count
// past the device's limits, a fluid block with no particle, ...).
SimulationSetup make_setup(const Scene& scene, const DeviceLimits& limits);

// Particles per second an emitter adds: nozzle flux (pi R^2 |v| in 3D, 2 R |v| in 2D) divided by
// the volume of one particle (spacing^d).
double emitter_rate(const Emitter& emitter, int dimension, float particle_spacing);

// How many particles an emitter has added by simulated time t (s), never above its capacity.
int emitted_by(const Emitter& emitter, int dimension, float particle_spacing, double time);

// Height of the shallow-water ground at (x, y), m.
float ground_height(const Scene& scene, glm::vec2 xy);

}  // namespace liquid
