// The value types of the LiquidNode's API, in one place: what a host passes in (options, force
// brushes, obstacle poses) and what it gets back (graph images, particles, diagnostics).
#pragma once

#include "engine/graph/render_graph.h"
#include "liquid/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace liquid {

// The liquid's surface: where rho / rho0 crosses this. The views draw it (RenderSettings::iso_level)
// and the exported surface follows it (SurfaceSettings::iso_level).
inline constexpr float k_default_iso_level = 0.5f;

// How a node stores and renders into 3D grids (README, "Devices and 3D paths"): 3D images reached
// through a geometry shader, 3D images whose vertex shaders write gl_Layer, or 2D atlases of the
// slices for devices with neither feature. 2D scenes need none.
enum class GridPath { GeometryShader, VertexLayer, Atlas };
inline constexpr GridPath k_grid_paths[] = {GridPath::GeometryShader, GridPath::VertexLayer, GridPath::Atlas};

// "geometry", "vertex-layer", "atlas": the names LiquidOptions, LIQUID_3D_PATH and --3d-path take.
const char* grid_path_name(GridPath path);
// Every path's name, joined: grid_path_names(", ", " or ") is "geometry, vertex-layer or atlas".
std::string grid_path_names(std::string_view separator, std::string_view last_separator);
// The path of that name, or nothing.
std::optional<GridPath> find_grid_path(std::string_view name);
// "'<text>' is not a 3D path (geometry, vertex-layer or atlas)", for messages.
std::string not_a_grid_path(std::string_view text);
// Throws ArgumentError naming `where` (a flag or variable) and the valid names.
GridPath parse_grid_path(std::string_view text, std::string_view where);

// How a node is created for a host's frame loop.
struct LiquidOptions {
  uint32_t frames_in_flight = 2;  // frames the GPU may still be running when add_to() is called
  int max_steps_per_frame = 0;    // 0 = the scene's substeps (uniform space is sized for this)
  double energy_bound_factor = 20.0;
  // How 3D grids are stored and rendered into (GridPath above). Empty: the environment
  // variable LIQUID_3D_PATH (geometry, vertex-layer or atlas) if set, else the best the device has.
  std::optional<GridPath> grid_path;
  // 3D: each step's grid passes compute only the cells near liquid (per slice, the rectangle within
  // a few kernel radii of the particles) and clear the rest; the particles come out bit for bit the
  // same. False computes every cell (for comparison: liquid_benchmark --whole-grid).
  bool active_region = true;
  // Where the node says, once, which 3D path and splat format it chose when that is worth knowing
  // ("liquid: 3D path: ..."); no sink, no messages.
  std::function<void(const std::string&)> log;
};

// An external force brush (the paper's f_ext): an acceleration (m/s^2) at `position` falling
// smoothly to zero at `radius`. A host maps mouse drags or gameplay forces to these.
struct ForceBrush {
  glm::vec3 position{0.0f};      // m
  float radius = 0.1f;           // m
  glm::vec3 acceleration{0.0f};  // m/s^2
};

// An obstacle's placement at one instant. A point p of the obstacle moves at
// velocity + angular_velocity x (p - center).
struct ObstaclePose {
  glm::vec3 center{0.0f};    // m
  glm::vec3 velocity{0.0f};  // m/s, of the centre
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // the shape's frame to world (w, x, y, z)
  glm::vec3 angular_velocity{0.0f};  // rad/s, world frame (2D: about z)
};

// A dynamic obstacle (a rigid body the liquid moves) after a step: its pose and the liquid's
// force and torque on it over that step (the pressure's and the no-inflow condition's, not gravity).
// In 2D, masses, forces and torques are per metre of depth.
struct BodyState {
  int obstacle = 0;          // index into the scene's obstacles
  ObstaclePose pose;
  glm::vec3 force{0.0f};     // N
  glm::vec3 torque{0.0f};    // N m, about the centre
  float mass = 0.0f;         // kg
};

// The graph images after the steps add_to() declared; valid for the rest of that graph. The grids
// are 3D images in 3D, or 2D atlases of their slices on the atlas path (LiquidOptions::grid_path).
struct LiquidImages {
  engine::graph::ImageHandle positions;      // RGBA32F particle texture, xyz m
  engine::graph::ImageHandle velocities;     // RGBA32F particle texture, xyz m/s
  engine::graph::ImageHandle splat;          // (sum w u, sum w), the last step's splat
  engine::graph::ImageHandle grid_velocity;  // (u', fluid flag)
  engine::graph::ImageHandle density;        // R16F rho / rho0
  engine::graph::ImageHandle bodies;         // the dynamic obstacles' state (the library's own layout;
                                             // a host reads it with LiquidNode::latest_bodies())
  // RGBA32F: the mesh obstacles' signed distance (m), one channel per mesh in scene order, exact
  // near their surfaces; invalid when the scene has no mesh obstacle.
  engine::graph::ImageHandle mesh_field;
  // RGBA32F secondary particles (Scene::whitewater), one texel a slot: xyz m and w the kind
  // (WhitewaterKind, 0 a free slot); xyz m/s and w the birth time (s). Invalid without whitewater.
  engine::graph::ImageHandle whitewater_positions;
  engine::graph::ImageHandle whitewater_velocities;
};

// What a secondary particle is, by the liquid's density where it is (Scene::whitewater); the
// values are the shaders' LIQUID_WHITEWATER_* codes (liquid/solver/whitewater.cpp checks them).
enum class WhitewaterKind : uint8_t { Spray = 1, Foam = 2, Bubble = 3 };

// A live secondary particle read back from the GPU. `id` is unique over the run (its slot and its
// birth), so a cache's points can be followed from frame to frame.
struct WhitewaterParticle {
  glm::vec3 position{0.0f};  // m
  glm::vec3 velocity{0.0f};  // m/s
  WhitewaterKind kind = WhitewaterKind::Foam;
  float age = 0.0f;          // s
  uint64_t id = 0;
};

// Particles read back from the GPU.
struct ParticleSnapshot {
  std::vector<glm::vec4> positions;   // active particles only
  std::vector<glm::vec4> velocities;
};

// Per-step health of a simulation: what the physics must conserve and respect (count and mass,
// finite state, walls and obstacles not crossed) and energy.
struct Diagnostics {
  int step = 0;
  double time = 0.0;               // s
  int active_particles = 0;
  int outside_domain = 0;          // particles beyond a wall
  int inside_obstacles = 0;        // particles inside an obstacle (signed distance < 0)
  int non_finite = 0;              // particles with a NaN or Inf component
  float max_density_ratio = 0.0f;  // max rho / rho0 over the grid
  double mass = 0.0;               // kg, active particles * particle mass
  double kinetic_energy = 0.0;     // J, sum 1/2 m |u|^2
  // J, sum m |g| (height above the domain's lowest point along gravity): zero for liquid lying on
  // the floor, so its share of the mechanical energy is the part gravity can still release.
  double potential_energy = 0.0;
  double mechanical_energy = 0.0;  // J, kinetic + potential
  double time_step = 0.0;          // s, the last step's dt
  float max_speed = 0.0f;          // m/s
  glm::vec3 center_of_mass{0.0f};  // m
  std::vector<BodyState> bodies;   // the dynamic obstacles, in scene order
};

// The parameters a host may change while the node runs (an interactive viewer's sliders); they
// take effect from the next step (LiquidNode::set_runtime_parameters).
struct RuntimeParameters {
  glm::vec3 gravity{0.0f};  // m/s^2
  float pic_ratio = 0.0f;   // 1 = PIC, 0 = FLIP
  float stiffness = 0.0f;   // k
};

// The live parameters a host's sliders can offer while the node keeps its present step, every one
// of them stable (LiquidNode::runtime_parameter_range): each range is what the step and the
// hydrostatic bound allow at the other parameters' present values (docs/integration.md).
struct RuntimeParameterRange {
  float max_gravity = 0.0f;                          // m/s^2, of |g|, at the stiffness given
  float min_stiffness = 0.0f, max_stiffness = 0.0f;  // at the gravity given
  float min_pic_ratio = 0.0f, max_pic_ratio = 1.0f;
};

// The whole simulation state between steps: restoring it into a node created from the same scene
// continues the run as if it had never stopped (bit for bit on the same driver), since every
// step rebuilds the grids from the particles. Force brushes are the host's input, not state.
struct Checkpoint {
  struct Pose {  // a set_obstacle_pose() in effect
    bool overridden = false;
    glm::vec3 center{0.0f}, velocity{0.0f};
    double since = 0.0;  // s
  };
  int step = 0;
  double time = 0.0;       // s
  double time_step = 0.0;  // s, the next step's (0: the scene's)
  int active = 0;
  std::vector<int> emitted;                      // per emitter
  std::vector<Pose> poses;                       // per obstacle
  std::vector<glm::vec4> positions, velocities;  // the whole particle textures, inactive texels too
  std::vector<glm::vec4> affine;                 // the affine transfer's C_p textures, one after another
  std::vector<glm::vec4> bodies;                 // the body-state texture (dynamic obstacles' state)
  std::vector<float> pressure;                   // the pressure projection's (p, psi) per texel of its grid (empty without)
  std::vector<glm::vec4> whitewater;  // the secondary particles' textures, positions then velocities (empty without)
};

}  // namespace liquid
