// Scene description in physical units (metres, seconds, kg/m^3, m/s^2), loaded from JSON and
// validated field by field. This is plain data: liquid/physics/setup.h turns it into grid sizes, particle
// mass and initial particles; the GPU side never sees JSON.
#pragma once

#include "liquid/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace liquid {

// What a scene file may hold, checked while it is read so that no input can make the loader spend
// more than a fraction of a second or more than a few tens of MB (a scene is a few kB; these are
// far above anything a scene needs). Each is refused with one line naming the file.
constexpr std::size_t k_max_scene_bytes = std::size_t(4) << 20;  // 4 MiB of JSON text
constexpr int k_max_scene_nesting = 8;          // the deepest scene is 6: obstacles[i].balls[j].center
constexpr int k_max_fluid_blocks = 1 << 14;     // also the most elements of any array in the file
constexpr int k_max_scene_values = 1 << 19;     // JSON values in the whole file (a 3D block is 13)

enum class SimulationMode {
  Liquid,        // the chapter's liquid: P = k (rho/rho0)^gamma with gravity
  ShallowWater,  // section 6, figure 4: 2D density read as water height, ground term as obstacle
};

// The splat's accumulation format. Auto: RGBA32F where the device can blend into it, else RGBA16F
// (the chapter's choice; many mobile GPUs cannot blend 32-bit floats). See choose_splat_format().
enum class SplatFormat { Auto, Rgba32f, Rgba16f };

// How the grid pass turns pressure into force. Chapter: the central differences of P (section 4,
// eq. 3). SplatAdjoint: of P smoothed with the splat's own kernel, the gradient of an energy, so
// resting water stays at rest (docs/physics.md).
enum class PressureForce { Chapter, SplatAdjoint };

// How the particles reach the grid. PointSprite: the chapter's splat (section 3), each particle a
// point of the kernel's diameter (once per slice it reaches in 3D) blended into the grid.
// Separable: each particle deposited into the 2^d cells around it (bilinear weights), then spread by
// one full-screen pass per axis with the kernel's 1D profile; far fewer blended fragments, and a
// tensor-product kernel instead of the radial one (docs/physics.md, "The separable splat").
enum class SplatMode { PointSprite, Separable };

// How velocity goes from the particles to the grid and back (section 5). PicFlip: the chapter's
// splat of u_p and its PIC/FLIP blend. Affine: each particle also carries its velocity's gradient
// C_p (APIC, Jiang et al. 2015), read back from the grid each step, and deposits
// u_p + C_p (x_i - x_p): a linear field goes through the transfer unchanged, also where the kernel
// is cut by the free surface, so the PIC share damps less of the waves (docs/physics.md, "Where
// sloshing loses its energy"). Needs the point-sprite splat.
enum class Transfer { PicFlip, Affine };

// A box of liquid filled with particles on a lattice of the scene's particle spacing.
struct FluidBlock {
  glm::vec3 min{0.0f};       // m (z ignored in 2D)
  glm::vec3 max{0.0f};       // m
  glm::vec3 velocity{0.0f};  // m/s, initial velocity of its particles
};

// A nozzle that adds particles over time (the paper's water jet), up to `capacity` particles.
struct Emitter {
  glm::vec3 position{0.0f};  // m, nozzle centre
  glm::vec3 velocity{0.0f};  // m/s, jet velocity (its direction is the nozzle axis)
  float radius = 0.0f;       // m, nozzle radius
  float start_time = 0.0f;   // s
  float stop_time = 1e30f;   // s
  int capacity = 0;          // most particles this emitter ever adds
};

// A shape's value is the code the shaders compare with (LIQUID_OBSTACLE_* in
// shaders/liquid/shared.h); a new shape takes the next value and its key in the list below.
enum class ObstacleShape { Sphere, Box, Metaballs, Mesh };
// The "shape" key's values, indexed by ObstacleShape.
inline constexpr const char* k_obstacle_shape_keys[] = {"sphere", "box", "metaballs", "mesh"};

// A closed triangle mesh (every edge shared by exactly two triangles of opposite orientation):
// positions in the mesh's own frame (m before `scale`), three indices per triangle, counter-clockwise
// seen from outside. A mesh obstacle is placed at world = obstacle centre + rotation * (scale * vertex).
struct TriangleMesh {
  std::vector<glm::vec3> vertices;
  std::vector<uint32_t> indices;
  std::string file;                          // where it was read from ("" for a host's mesh)
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // the mesh's own orientation (identity)
  float scale = 1.0f;                        // uniform
};

struct Metaball {
  glm::vec3 center{0.0f};  // m
  float radius = 0.0f;     // m, radius of influence
};

// A rigid obstacle: an analytic shape whose smooth distance field adds an artificial pressure in
// the grid pass (section 6). It may move: position(t) = center + velocity t + amplitude sin(2 pi f t),
// or, when dynamic, as a rigid body the liquid and gravity move (docs/physics.md, "Bodies that
// float"), starting at `center` with `velocity`.
struct Obstacle {
  ObstacleShape shape = ObstacleShape::Sphere;
  glm::vec3 center{0.0f};        // m
  float radius = 0.0f;           // m (sphere)
  glm::vec3 half_extent{0.0f};   // m (box)
  std::vector<Metaball> balls;   // metaballs: surface where sum (1 - d^2/R^2)^2 = threshold;
                                 // centres relative to `center` (the JSON gives them in domain
                                 // coordinates; the parser puts `center` at their centroid)
  float threshold = 0.5f;        // metaballs iso level, in (0, 1)
  TriangleMesh mesh;             // mesh: the triangles, their rotation and scale about `center`
  glm::vec3 velocity{0.0f};      // m/s, constant drift
  glm::vec3 oscillation_amplitude{0.0f};  // m
  float oscillation_frequency = 0.0f;     // Hz
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // the shape's frame to world (w, x, y, z); 2D: about z
  // rad/s, world frame (2D: about z only): a scripted spin about `center`, the shape turned to
  // angleAxis(|w| t, w / |w|) * rotation at time t, its material moving at w x (p - center); a
  // dynamic obstacle's initial angular velocity.
  glm::vec3 angular_velocity{0.0f};
  bool dynamic = false;  // a rigid body (spheres and boxes): exactly one of density and mass is > 0
  float density = 0.0f;  // kg/m^3
  float mass = 0.0f;     // kg (2D: kg per metre of depth)
};

// Shallow-water ground: height b(x, y) = sum of Gaussian hills, in metres above the bed.
struct GroundHill {
  glm::vec2 center{0.0f};  // m
  float height = 0.0f;     // m
  float width = 0.0f;      // m, Gaussian standard deviation
};

struct Camera {
  glm::vec3 position{0.0f};  // m
  glm::vec3 target{0.0f};    // m
  float fov_y_degrees = 45.0f;
};

// Acoustic CFL numbers (dt c / h) of the two regimes (docs/physics.md, "Longer steps"). The
// chapter's: r blended per step, FLIP velocity noise grows above about 0.2 on rest_pool_2d. The
// splat-adjoint pressure with the PIC blend per second (pic_ratio_reference_step): its pressure is
// smoothed twice by the kernel, so the shortest waves it carries are about 2 r h long, and
// dam_break_2d (r = 3 cells) runs stable at 2.4 and explodes at 3.6; the shipped scenes stay at
// about half of 2.4, scaled by r / 3 for another kernel radius.
inline constexpr double k_acoustic_cfl_chapter = 0.16;
inline constexpr double k_acoustic_cfl_smoothed = 1.3;
inline constexpr double k_acoustic_cfl_smoothed_stable = 2.4;  // the largest measured stable
// The largest acoustic_cfl adaptive_time_step accepts: in the chapter's regime, and with the
// splat-adjoint pressure and pic_ratio_reference_step.
inline constexpr double k_max_acoustic_cfl_chapter = 1.0;
inline constexpr double k_max_acoustic_cfl = 2.0;

// The shipped model's projection iterations (the default), and the chapter's PIC share (section
// 5.1's r), which a scene naming the chapter's pressure gets by default.
inline constexpr int k_default_projection_iterations = 4;
inline constexpr float k_chapter_pic_ratio = 0.05f;

// The range a scene's time_step may take, s.
inline constexpr double k_min_time_step = 1e-6;
inline constexpr double k_max_time_step = 0.1;

// CFL numbers of the adaptive step: dt = min(time_step, acoustic_cfl h / (c + |u|max),
// velocity_cfl h / |u|max), with c the Tait form's speed of sound at the densest cell.
struct AdaptiveTimeStep {
  float acoustic_cfl = float(k_acoustic_cfl_chapter);
  float velocity_cfl = 0.4f;
};

// Secondary particles: spray, foam and bubbles (Ihmsen et al. 2012, "Unified spray, foam and
// bubbles for particle-based fluids"; docs/whitewater.md). Each liquid particle owns
// `slots_per_particle` of them and spawns into its free ones at a rate set by its potentials for
// trapped air (neighbours approaching it) and a wave crest (a convex surface moving outward), scaled
// by its speed; each is then spray, foam or a bubble by the liquid's density where it is. One-way:
// the liquid never reads them, so its results are the same with or without.
struct Whitewater {
  int slots_per_particle = 2;          // capacity, in secondary particles per liquid particle
  float lifetime = 2.0f;               // s, mean life (each one's is 0.5 to 1.5 times it)
  float trapped_air_rate = 200.0f;      // 1/s per liquid particle at full trapped-air potential
  float crest_rate = 100.0f;           // 1/s per liquid particle at full crest potential
  glm::vec2 trapped_air_range{0.1f, 0.8f};  // m/s: the weighted speed of approach mapped to 0..1
  glm::vec2 crest_range{10.0f, 40.0f};      // 1/m: the surface's curvature mapped to 0..1
  glm::vec2 speed_range{0.3f, 1.5f};        // m/s: the particle's speed mapped to 0..1 (scales both)
  float spray_density = 0.3f;          // rho / rho0 below which a secondary particle is spray
  float bubble_density = 0.75f;        // above which it is a bubble (foam between)
  float spray_drag = 0.2f;             // 1/s: spray's air drag
  float bubble_buoyancy = 2.0f;        // a bubble rises at this many times -gravity
  float bubble_drag = 8.0f;            // 1/s: a bubble's pull toward the liquid's velocity
};

struct Scene {
  std::string name;                 // file stem unless "name" is given
  // Where it was read from (the file, or parse_scene's source_name): the prefix of every error
  // found later (by make_setup). Empty for a scene built in code, whose errors start with `name`.
  std::string source;
  int dimension = 2;                // 2 or 3
  SimulationMode mode = SimulationMode::Liquid;
  glm::vec3 domain{1.0f};           // m, box [0, domain]; z ignored in 2D
  std::optional<int> grid_resolution;  // cells along the longest axis; default two particle spacings a cell
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s^2
  float particle_spacing = 0.01f;   // m, lattice spacing of fluid blocks (sets particle mass)
  float density = 1000.0f;          // kg/m^3, the liquid's density (particle mass = density * spacing^d)
  std::optional<float> rest_density;  // kg/m^3 rho0; empty = computed from the initial uniform lattice
  float stiffness = 50.0f;          // k, m^2/s^2 (specific pressure; speed of sound c = sqrt(k gamma))
  float gamma = 5.0f;               // pressure exponent
  float kernel_radius_cells = 3.0f; // splat radius r, in grid cells
  // r in the PIC/FLIP blend: the shipped model's; a scene file that names the chapter's pressure
  // gets k_chapter_pic_ratio when it leaves the key out.
  float pic_ratio = 0.002f;
  // s; when set, pic_ratio is the blend over a step of this length and steps of other lengths
  // blend at the same rate per second (liquid/physics/pic_blend.h); empty: r per step, as the chapter.
  std::optional<float> pic_ratio_reference_step;
  // s, one simulation step (with adaptive_time_step, the largest); 0, which a scene file cannot
  // write (the key left out reads as 0): the regime's step at the scene's cell size (the acoustic
  // CFL the shipped scenes keep to; liquid/physics/time_step.h).
  float time_step = 0.0f;
  int substeps = 8;                 // steps per rendered frame
  float wall_margin_cells = 0.5f;   // particles are clamped this many cells inside the walls (or where they started)
  SplatFormat splat_format = SplatFormat::Auto;
  // The defaults are the shipped physical scenes' model: the splat-adjoint pressure, solved as a
  // projection, on the separable splat. The chapter's is named (the paper_* scenes).
  PressureForce pressure_force = PressureForce::SplatAdjoint;
  SplatMode splat = SplatMode::Separable;
  Transfer transfer = Transfer::PicFlip;
  // beta: each step the particle pass moves every particle down the gradient of how far the
  // separable splat's deposit (a kernel one cell wide) reads above the wide kernel's density, by
  // beta cells per unit of that excess per cell, so particles do not pack tighter than the
  // pressure's kernel sees (docs/physics.md, "Still water that keeps its volume"). 0: off. Needs the
  // separable splat.
  float position_correction = 0.0f;
  // Jacobi iterations of a pressure projection per step (0: none, the pressure is the equation of
  // state's); splat-adjoint pressure only, liquid mode only. A scene file that names the chapter's
  // pressure gets 0 when it leaves the key out.
  int projection_iterations = k_default_projection_iterations;
  float rest_depth = 0.1f;          // m, shallow water: water height where rho = rho0
  std::vector<FluidBlock> fluid_blocks;
  std::vector<Emitter> emitters;
  std::vector<Obstacle> obstacles;
  std::vector<GroundHill> ground;   // shallow water only
  std::optional<Camera> camera;     // 3D rendering; a default looks at the domain
  std::optional<Whitewater> whitewater;  // secondary particles; none when empty
  // Steps sized from the state by CFL conditions (liquid/physics/time_step.h); empty: every step is
  // time_step (the chapter's fixed step).
  std::optional<AdaptiveTimeStep> adaptive_time_step;
  // For code that studies instability on purpose (not a scene file key): a fixed time_step past the
  // regime's stable step is run instead of refused by make_setup.
  bool allow_unstable_time_step = false;
};

// The long-step regime: the splat-adjoint pressure with the PIC blend per second
// (pic_ratio_reference_step) or solved as a projection, the one where steps past the chapter's
// acoustic CFL stay stable and accurate (docs/physics.md, "Longer steps").
bool long_step_regime(const Scene& scene);

// What the solver runs for a scene: shallow water takes neither the splat-adjoint pressure nor the
// projection, whatever those fields hold (their defaults are the liquid's).
bool uses_splat_adjoint_pressure(const Scene& scene);
int projection_iterations_of(const Scene& scene);

// Parses and validates a scene. `source_name` prefixes every error message.
Scene parse_scene(const std::string& json_text, const std::string& source_name);

// Reads and parses a file; a missing, unreadable or oversized file, or a folder, is a SceneError
// naming the path.
Scene load_scene(const std::filesystem::path& path);

}  // namespace liquid
