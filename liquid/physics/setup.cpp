#include "liquid/physics/setup.h"

#include "liquid/scene/format.h"
#include "liquid/scene/limits.h"

#include "liquid/physics/body.h"
#include "liquid/physics/kernel.h"
#include "liquid/physics/obstacles.h"
#include "liquid/physics/time_step.h"
#include "liquid/physics/wall_coverage.h"
#include "shaders/liquid/shared.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace liquid {
namespace {

// floor((max - min) / s + epsilon): a block whose extent is a whole number of spacings gets that
// many particles even when the float division lands just below the integer.
constexpr double k_lattice_epsilon = 1e-4;
// CPU memory guard: initial particles are held in two vec4 arrays (32 bytes each).
constexpr std::int64_t k_max_initial_particles = std::int64_t(1) << 26;

constexpr double k_pi = 3.14159265358979323846;

// "dam.json: fluid_blocks: ...": the file (the name for a scene built in code), then the field.
[[noreturn]] void fail(const Scene& scene, const std::string& field, const std::string& reason) {
  throw SceneError((scene.source.empty() ? scene.name : scene.source) + ": " + field + ": " + reason);
}

// A rigid body must start wholly inside the domain: the wall contact keeps its box there
// (body_wall_half_extent), so one placed across a wall, or wider than the domain, would be moved
// at its first step without a word.
void check_body_inside_domain(const Scene& scene, size_t index) {
  const Obstacle& o = scene.obstacles[index];
  const glm::vec3 e = body_wall_half_extent(o);
  // A mesh's box is its principal box about its centre of mass, larger than its bounding box when
  // the two centres differ: say which box, or the figure would not match the file's.
  const char* shape = o.shape == ObstacleShape::Mesh ? "mesh's box about its centre of mass (what the walls hold in)"
                                                     : k_obstacle_shape_keys[size_t(o.shape)];
  const std::string field = "obstacles[" + std::to_string(index) + "]";
  for (int a = 0; a < scene.dimension; ++a) {
    const char axis = "xyz"[a];
    // A hair of slack for a body resting on a wall, its numbers written with rounded decimals.
    const float slack = 1e-5f * scene.domain[a];
    if (2.0f * e[a] > scene.domain[a] + slack)
      fail(scene, field, std::string("the dynamic ") + shape + " is " + format_number(2.0f * e[a]) + " m across along " +
                             axis + ", wider than the domain's " + format_number(scene.domain[a]) +
                             " m; a body must fit inside the domain");
    const float lo = o.center[a] - e[a], hi = o.center[a] + e[a];
    if (lo < -slack || hi > scene.domain[a] + slack)
      fail(scene, field, std::string("the dynamic ") + shape + " reaches " + axis + " = " +
                             format_number(lo < -slack ? lo : hi) + " m, outside the domain's [0, " +
                             format_number(scene.domain[a]) + "] m; a body must start wholly inside the domain");
  }
}

// Particles per axis of a block's lattice (z = 1 in 2D).
glm::ivec3 lattice_counts(const FluidBlock& block, int dimension, double spacing) {
  glm::ivec3 counts(1);
  for (int a = 0; a < dimension; ++a) {
    const double extent = double(block.max[a]) - double(block.min[a]);
    counts[a] = int(std::min(std::floor(extent / spacing + k_lattice_epsilon), 1e9));
  }
  return counts;
}

std::int64_t lattice_size(glm::ivec3 counts) { return std::int64_t(counts.x) * counts.y * counts.z; }

// The smallest power of two >= ceil(sqrt(n)) (at least 1) by ceil(n / W).
glm::i64vec2 particle_texture_size(std::int64_t capacity) {
  std::int64_t side = std::int64_t(std::ceil(std::sqrt(double(capacity))));
  while (side * side < capacity) ++side;  // guard the square root's rounding
  std::int64_t width = 1;
  while (width < side) width *= 2;
  return {width, std::max<std::int64_t>(1, (capacity + width - 1) / width)};
}

std::string describe_grid(glm::ivec3 cells) {
  return std::to_string(cells.x) + " x " + std::to_string(cells.y) + " x " + std::to_string(cells.z);
}

// Chooses the cells per axis and the cell size (square/cubic cells, longest_axis_cells along the
// longest side).
void choose_grid(const Scene& scene, SimulationSetup& setup) {
  const double h = scene_cell_size(scene);
  setup.grid_cells = glm::ivec3(1);
  for (int a = 0; a < scene.dimension; ++a)
    setup.grid_cells[a] = int(std::max(1.0, std::min(std::round(double(scene.domain[a]) / h), 1e9)));
  setup.cell_size = float(h);
  // Cells are square/cubic, so the box is snapped to whole cells (the shorter axes may grow or
  // shrink by up to half a cell). In 2D the z extent is the single cell's thickness (unused).
  setup.domain = glm::vec3(setup.grid_cells) * float(h);
}

void check_grid_limits(const Scene& scene, const SimulationSetup& setup, const DeviceLimits& limits) {
  const glm::ivec3 cells = setup.grid_cells;
  const bool three_d = scene.dimension == 3;
  const int per_axis = three_d ? limits.max_image_dimension_3d : limits.max_image_dimension_2d;
  const char* limit_name = three_d ? "max_image_dimension_3d" : "max_image_dimension_2d";
  // A default grid says where it came from, so the user knows which key to set.
  const std::string from = scene.grid_resolution ? "" : " (the default: " + format_number(k_default_spacings_per_cell) +
                                                             " particle spacings a cell; set grid_resolution)";
  for (int a = 0; a < scene.dimension; ++a)
    if (cells[a] > per_axis)
      fail(scene, "grid_resolution",
           "grid " + describe_grid(cells) + " exceeds the device limit of " + std::to_string(per_axis) +
               " texels per axis (" + limit_name + ")" + from);
  if (three_d && cells.z > limits.max_framebuffer_layers)
    fail(scene, "grid_resolution",
         "grid " + describe_grid(cells) + " needs " + std::to_string(cells.z) +
             " framebuffer layers, past the device limit of " + std::to_string(limits.max_framebuffer_layers) +
             " (max_framebuffer_layers)" + from);
}

// Whether a lattice point at t = 0 lies in the part of an obstacle's band where its artificial
// density (section 6: rho0 (1 - d / band), added to the liquid's) would push it away: such a
// particle, and the liquid around it, is blasted out on the first steps (a floating block around a
// sphere reached 6 m/s in 20 steps when only points within half a spacing were left out). So the
// block is carved out to a share of the band, measured on that block (2D and 3D) for each pressure
// force: the chapter's differences P itself, and carving to half the band still left 0.8 m/s,
// three quarters leaves it falling freely (0.026 m/s); the splat adjoint differences P smoothed
// by the kernel once more, so the push reaches a kernel radius further: 0.32 m/s at three
// quarters, 0.052 at one band, free fall at one and a half. Under the pressure projection a static
// obstacle adds no density (it is solid to the solve): the block is carved to the particles' skin
// only, where the particle pass would move them; a band's gap would drop the pool into it.
float carved_share(const Scene& scene) {
  if (projection_iterations_of(scene) > 0) return float(LIQUID_OBSTACLE_SKIN_CELLS / double(scene.kernel_radius_cells));
  return uses_splat_adjoint_pressure(scene) ? 1.5f : 0.75f;
}

std::vector<PlacedObstacle> obstacles_at_start(const Scene& scene, float band) {
  std::vector<PlacedObstacle> placed;
  for (const Obstacle& o : scene.obstacles)
    placed.emplace_back(o, scripted_pose(o, 0.0), scene.dimension, 2.0f * carved_share(scene) * band);
  return placed;
}

// A dynamic obstacle adds no artificial density (its liquid reads the body's kernel coverage
// instead), so only its inside is carved: the band would take a third of a small pool and drop the
// body into the gap before the liquid has any pressure.
bool inside_any_obstacle(const Scene& scene, const std::vector<PlacedObstacle>& obstacles, glm::vec3 p, float band) {
  for (size_t i = 0; i < obstacles.size(); ++i)
    if (obstacles[i].distance(p) < (scene.obstacles[i].dynamic ? 0.0f : carved_share(scene) * band)) return true;
  return false;
}

}  // namespace

int single_gravity_axis(int dimension, glm::vec3 gravity) {
  int axis = -1;
  for (int a = 0; a < dimension; ++a)
    if (gravity[a] != 0.0f) axis = axis < 0 ? a : dimension;  // more than one: none
  return axis < dimension ? axis : -1;
}

namespace {

// Still water under the splat-adjoint pressure holds its weight by compression: the solver's
// acceleration is -grad P + g, so at rest P = |g| d at depth d and the Tait form gives
// rho / rho0 = (1 + |g| d / k)^(1 / gamma). A block resting on the wall gravity points into
// (gravity along one axis) starts so compressed: the lattice point at uncompressed depth eta
// below the block's top goes to the depth d(eta) that holds the same mass above it,
//   eta(d) = integral_0^d (1 + g x / k)^(1/gamma) dx
//          = (k / g) ((1 + g d / k)^(1 + 1/gamma) - 1) / (1 + 1/gamma),
// inverted in closed form. Started uncompressed, a pool falls onto itself and rings for seconds.
// Not under the pressure projection: that liquid is incompressible, rest density at every depth,
// and its density correction would spread a compressed start back out, lifting the whole pool
// while its first waves run (docs/physics.md, "The density correction").
class HydrostaticStart {
 public:
  HydrostaticStart(const Scene& scene, const FluidBlock& block, glm::ivec3 counts, const SimulationSetup& setup) {
    if (!uses_splat_adjoint_pressure(scene) || projection_iterations_of(scene) > 0)
      return;
    const int axis = single_gravity_axis(scene.dimension, scene.gravity);
    if (axis < 0 || scene.stiffness <= 0.0f) return;
    const double s = scene.particle_spacing;
    const bool down = scene.gravity[axis] < 0.0f;
    const double bottom = down ? double(block.min[axis]) : double(block.min[axis]) + counts[axis] * s;
    floor_ = down ? 0.0 : double(setup.domain[axis]);
    if (std::abs(bottom - floor_) > s) return;  // not resting on that wall: falls freely
    axis_ = axis;
    top_ = down ? double(block.min[axis]) + counts[axis] * s : double(block.min[axis]);
    g_over_k_ = std::abs(double(scene.gravity[axis])) / double(scene.stiffness);
    exponent_ = 1.0 + 1.0 / double(scene.gamma);
  }

  // The point p of the uncompressed lattice, moved to its compressed height.
  glm::dvec3 place(glm::dvec3 p) const {
    if (axis_ < 0) return p;
    const double height = std::abs(top_ - floor_), eta = std::abs(top_ - p[axis_]);
    const double from_floor = depth(height) - depth(eta);
    p[axis_] = floor_ + (top_ > floor_ ? from_floor : -from_floor);
    return p;
  }

 private:
  // expm1 and log1p keep it exact where g eta / k is tiny (pow(1 + x, p) - 1 cancels to 0).
  double depth(double eta) const {
    return std::expm1(std::log1p(exponent_ * g_over_k_ * eta) / exponent_) / g_over_k_;
  }
  int axis_ = -1;
  double floor_ = 0.0, top_ = 0.0, g_over_k_ = 0.0, exponent_ = 1.0;
};

// Fills one block's lattice: min + (i + 0.5) s per axis, no jitter, computed in double, leaving
// out the points in or next to obstacles. A block whose extent is a whole number of spacings is
// filled symmetrically, so mirrored blocks give mirrored particles. Fails if the lattice pokes out
// of the snapped domain.
void fill_block(const Scene& scene, size_t index, glm::ivec3 counts, SimulationSetup& setup) {
  const FluidBlock& block = scene.fluid_blocks[index];
  const double s = scene.particle_spacing;
  for (int a = 0; a < scene.dimension; ++a) {
    const double first = double(block.min[a]) + 0.5 * s, last = double(block.min[a]) + (counts[a] - 0.5) * s;
    if (first < 0.0 || last > double(setup.domain[a]))
      fail(scene, "fluid_blocks[" + std::to_string(index) + "]", "particles span [" + format_number(first) + ", " +
                      format_number(last) + "] m on axis " + std::to_string(a) +
                      ", outside the domain snapped to whole cells [0, " + format_number(setup.domain[a]) + "] m");
  }
  const glm::vec4 velocity(block.velocity.x, block.velocity.y, scene.dimension == 3 ? block.velocity.z : 0.0f, 0.0f);
  const HydrostaticStart hydrostatic(scene, block, counts, setup);
  const std::vector<PlacedObstacle> obstacles = obstacles_at_start(scene, setup.obstacle_band);
  for (int k = 0; k < counts.z; ++k)
    for (int j = 0; j < counts.y; ++j)
      for (int i = 0; i < counts.x; ++i) {
        const glm::vec3 p(hydrostatic.place({double(block.min.x) + (i + 0.5) * s, double(block.min.y) + (j + 0.5) * s,
                                             scene.dimension == 3 ? double(block.min.z) + (k + 0.5) * s : 0.0}));
        if (inside_any_obstacle(scene, obstacles, p, setup.obstacle_band)) continue;
        setup.positions.emplace_back(p, 1.0f);
        setup.velocities.push_back(velocity);
      }
}

// Average over sub-cell offsets of sum_p w(x_p - x_cell) for an infinite lattice of spacing
// `spacing_cells` (in cells), with the scene's splat kernel: the summed weight a cell sees inside
// uniform liquid.
double lattice_weight_sum(SplatMode mode, int dimension, double spacing_cells, double radius_cells) {
  if (radius_cells / spacing_cells > k_max_summed_lattice_ratio)
    return splat_kernel_integral_cells(mode, dimension, radius_cells) / std::pow(spacing_cells, dimension);
  const int reach = int(std::ceil(splat_kernel_support(mode, radius_cells) / spacing_cells)) + 1;
  const int offsets_z = dimension == 3 ? k_lattice_offsets_per_axis : 1;
  double total = 0.0;
  int samples = 0;
  for (int oz = 0; oz < offsets_z; ++oz)
    for (int oy = 0; oy < k_lattice_offsets_per_axis; ++oy)
      for (int ox = 0; ox < k_lattice_offsets_per_axis; ++ox) {
        const glm::dvec3 offset = (glm::dvec3(ox, oy, oz) + 0.5) / double(k_lattice_offsets_per_axis);
        const int kz_reach = dimension == 3 ? reach : 0;
        double sum = 0.0;
        for (int kz = -kz_reach; kz <= kz_reach; ++kz)
          for (int ky = -reach; ky <= reach; ++ky)
            for (int kx = -reach; kx <= reach; ++kx) {
              const double dx = (kx + offset.x) * spacing_cells;
              const double dy = (ky + offset.y) * spacing_cells;
              const double dz = dimension == 3 ? (kz + offset.z) * spacing_cells : 0.0;
              sum += splat_kernel_weight(mode, dx, dy, dz, radius_cells);
            }
        total += sum;
        ++samples;
      }
  return total / samples;
}

// Counts the initial particles and the capacity, failing on an empty block or too many particles.
std::vector<glm::ivec3> count_particles(const Scene& scene, std::int64_t& initial, std::int64_t& capacity) {
  std::vector<glm::ivec3> counts;
  initial = 0;
  for (size_t i = 0; i < scene.fluid_blocks.size(); ++i) {
    counts.push_back(lattice_counts(scene.fluid_blocks[i], scene.dimension, scene.particle_spacing));
    const std::int64_t n = lattice_size(counts.back());
    if (n <= 0)
      fail(scene, "fluid_blocks[" + std::to_string(i) + "]", "produces no particle at spacing " +
                      format_number(scene.particle_spacing) + " m (the block is thinner than one spacing)");
    initial += n;
  }
  if (initial > k_max_initial_particles)
    fail(scene, "fluid_blocks", "hold " + std::to_string(initial) + " particles, more than the supported " +
                    std::to_string(k_max_initial_particles) + "; increase particle_spacing");
  capacity = initial;
  for (const Emitter& e : scene.emitters) capacity += std::max(0, e.capacity);
  if (capacity <= 0) fail(scene, "fluid_blocks", "the scene has no particle: add a fluid block or an emitter");
  if (capacity > std::numeric_limits<int>::max())
    fail(scene, "emitters", "capacity of " + std::to_string(capacity) + " particles does not fit a 32-bit index");
  return counts;
}

void check_emitters(const Scene& scene, const SimulationSetup& setup) {
  for (size_t i = 0; i < scene.emitters.size(); ++i)
    for (int a = 0; a < scene.dimension; ++a)
      if (scene.emitters[i].position[a] < 0.0f || scene.emitters[i].position[a] > setup.domain[a])
        fail(scene, "emitters[" + std::to_string(i) + "].position", "is outside the domain snapped to whole cells (" +
                        format_number(setup.domain[a]) + " m on axis " + std::to_string(a) + ")");
}

// A fixed step past the regime's stable one would explode in the first steps: refuse it before the
// run, saying what the scene could do instead (adaptive steps adapt, so they are not refused).
void check_time_step(const Scene& scene, const SimulationSetup& setup) {
  const double largest = largest_stable_time_step(setup);
  if (scene.adaptive_time_step || scene.allow_unstable_time_step || setup.time_step <= largest) return;
  const double sound = speed_of_sound(setup, 1.0), fall = fall_speed(setup);
  fail(scene, "time_step",
       format_number(setup.time_step) + " s is past the longest stable step of this scene, " + format_number(largest) +
           " s (an acoustic CFL of " + format_number(stable_acoustic_cfl(setup)) + " in " +
           (setup.long_steps ? "the long-step regime" : "the chapter's regime") + " on cells of " +
           format_number(setup.cell_size) + " m, for sound at " + format_number(sound) + " m/s and a fall across the domain at " +
           format_number(fall) + " m/s); lower it, leave it out for the regime's step, or add adaptive_time_step");
}

}  // namespace

double longest_side(glm::vec3 domain, int dimension) {
  double longest = 0.0;
  for (int a = 0; a < dimension; ++a) longest = std::max(longest, double(domain[a]));
  return longest;
}

int longest_axis_cells(const Scene& scene) {
  if (scene.grid_resolution) return *scene.grid_resolution;
  const double cells =
      std::round(longest_side(scene.domain, scene.dimension) / (k_default_spacings_per_cell * scene.particle_spacing));
  return int(std::clamp(cells, double(k_min_grid_cells), 1e9));
}

double scene_cell_size(const Scene& scene) {
  return longest_side(scene.domain, scene.dimension) / longest_axis_cells(scene);
}

PressureLaw pressure_law(const Scene& scene) {
  if (scene.mode == SimulationMode::ShallowWater) return {glm::length(scene.gravity) * scene.rest_depth, 1.0f};
  return {scene.stiffness, scene.gamma};
}

double kernel_integral_cells(int dimension, double radius_cells) {
  if (dimension == 2) return k_pi * radius_cells * radius_cells / 4.0;
  if (dimension == 3) return 64.0 * k_pi * radius_cells * radius_cells * radius_cells / 315.0;
  throw ArgumentError("kernel_integral_cells: dimension must be 2 or 3, got " + std::to_string(dimension));
}

double splat_kernel_integral_cells(SplatMode mode, int dimension, double radius_cells) {
  if (mode == SplatMode::PointSprite) return kernel_integral_cells(dimension, radius_cells);
  double taps = 0.0;
  const int reach = separable_reach(radius_cells);
  for (int j = -reach; j <= reach; ++j) taps += kernel_weight(double(j) * j, radius_cells);
  return std::pow(taps, dimension);
}

SimulationSetup make_setup(const Scene& scene, const DeviceLimits& limits) {
  if (scene.dimension != 2 && scene.dimension != 3)
    fail(scene, "dimension", "must be 2 or 3, got " + std::to_string(scene.dimension));
  // Again for a scene built in code; a file's was checked when read.
  check_list_limits(scene);
  check_projection(scene);
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].dynamic) check_body_inside_domain(scene, i);
  SimulationSetup setup;
  setup.dimension = scene.dimension;
  setup.shallow_water = scene.mode == SimulationMode::ShallowWater;
  setup.time_step = float(scene_time_step(scene));
  setup.particle_spacing = scene.particle_spacing;
  setup.kernel_radius_cells = scene.kernel_radius_cells;
  setup.pic_ratio = scene.pic_ratio;
  setup.pic_ratio_reference_step = scene.pic_ratio_reference_step.value_or(0.0f);
  setup.splat_adjoint_pressure = uses_splat_adjoint_pressure(scene);
  setup.splat = scene.splat;
  setup.long_steps = long_step_regime(scene);
  setup.rest_depth = scene.rest_depth;
  const int d = scene.dimension;

  std::int64_t initial = 0, capacity = 0;
  const std::vector<glm::ivec3> counts = count_particles(scene, initial, capacity);
  const glm::i64vec2 texture = particle_texture_size(capacity);
  if (texture.x > limits.max_image_dimension_2d || texture.y > limits.max_image_dimension_2d)
    fail(scene, scene.emitters.empty() ? "fluid_blocks" : "emitters",
         "capacity of " + std::to_string(capacity) + " particles needs a " + std::to_string(texture.x) + " x " +
             std::to_string(texture.y) + " particle texture, past the device limit of " +
             std::to_string(limits.max_image_dimension_2d) + " texels per axis (max_image_dimension_2d)");
  setup.initial_particles = int(initial);
  setup.capacity = int(capacity);
  setup.particle_texture = glm::ivec2(texture);

  choose_grid(scene, setup);
  // The artificial obstacle density falls to zero one kernel radius outside the surface.
  setup.obstacle_band = scene.kernel_radius_cells * setup.cell_size;
  check_grid_limits(scene, setup, limits);
  const double h = setup.cell_size;
  const double spacing = scene.particle_spacing;
  const double radius = scene.kernel_radius_cells;
  // Farther apart than the kernel radius, no particle would see another: no pressure at all.
  if (spacing >= radius * h)
    fail(scene, "particle_spacing", format_number(spacing) + " m is not below the kernel radius (" +
                    format_number(radius) + " cells of " + format_number(h) +
                    " m); lower particle_spacing or grid_resolution");
  check_emitters(scene, setup);

  setup.positions.reserve(size_t(initial));
  setup.velocities.reserve(size_t(initial));
  for (size_t i = 0; i < scene.fluid_blocks.size(); ++i) fill_block(scene, i, counts[i], setup);
  // Obstacles may have carved lattice points out: the counts are those actually placed, and the
  // texture fits them (the device limit was checked on the full lattice, an upper bound; the
  // default grid stays sized from it).
  const int carved = setup.initial_particles - int(setup.positions.size());
  setup.initial_particles -= carved;
  setup.capacity -= carved;
  if (setup.capacity <= 0) fail(scene, "obstacles", "cover every particle of the fluid blocks");
  setup.particle_texture = glm::ivec2(particle_texture_size(setup.capacity));

  const double mass = scene.density * std::pow(spacing, d);
  const double scale = mass / (std::pow(h, d) * splat_kernel_integral_cells(scene.splat, d, radius));
  setup.particle_mass = float(mass);
  setup.density_scale = float(scale);
  setup.rest_density = scene.rest_density ? *scene.rest_density
                                          : float(scale * lattice_weight_sum(scene.splat, d, spacing / h, radius));

  const PressureLaw law = pressure_law(scene);
  setup.stiffness = law.stiffness;
  setup.gamma = law.gamma;
  // Shallow water: P = k rho / rho0 = g * (water height), and the plane is horizontal. Else z is 0
  // in 2D (the parser fills it so).
  setup.gravity = scene.mode == SimulationMode::ShallowWater ? glm::vec3(0.0f) : scene.gravity;
  setup.wall_margin = scene.wall_margin_cells * setup.cell_size;
  setup.wall_share_beyond = wall_share_beyond(scene, spacing / h, gpu::k_wall_table_size);
  setup.body_share_beyond = body_share_beyond(scene, spacing / h, gpu::k_wall_table_size);
  for (const Obstacle& o : scene.obstacles) {
    BodyConstants& b = setup.bodies.emplace_back();
    if (!o.dynamic) continue;
    b.mass = float(body_mass(o, setup.dimension));
    b.inertia = body_inertia(o, setup.dimension);
    b.added_mass = float(body_added_mass(o, setup.dimension, setup.rest_density, setup.cell_size));
    b.added_inertia_ratio = float(body_added_inertia_ratio(o, setup.dimension, b.added_mass));
    if (o.shape != ObstacleShape::Mesh) continue;
    b.shape_half_size = body_shape_half_size(o, setup.kernel_radius_cells, setup.cell_size);
    b.shape_half_extent = mesh_half_extent(o.mesh);
  }
  check_time_step(scene, setup);
  return setup;
}

double emitter_rate(const Emitter& emitter, int dimension, float particle_spacing) {
  const double speed = glm::length(glm::dvec3(emitter.velocity));
  const double r = emitter.radius;
  const double s = particle_spacing;
  return dimension == 3 ? k_pi * r * r * speed / (s * s * s) : 2.0 * r * speed / (s * s);
}

int emitted_by(const Emitter& emitter, int dimension, float particle_spacing, double time) {
  const double elapsed = std::min(time, double(emitter.stop_time)) - double(emitter.start_time);
  if (!(elapsed > 0.0)) return 0;
  const double count = std::floor(emitter_rate(emitter, dimension, particle_spacing) * elapsed);
  return int(std::clamp(count, 0.0, double(emitter.capacity)));
}

float ground_height(const Scene& scene, glm::vec2 xy) {
  double height = 0.0;
  for (const GroundHill& hill : scene.ground) {
    const glm::vec2 d = xy - hill.center;
    height += double(hill.height) * std::exp(-double(glm::dot(d, d)) / (2.0 * double(hill.width) * hill.width));
  }
  return float(height);
}

}  // namespace liquid
