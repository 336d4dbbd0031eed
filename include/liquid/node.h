// LiquidNode: the one entry point a host engine uses. Created from a scene, it adds the solver's
// passes (splat -> grid -> particle update, per step) to the host's render graph each frame,
// exposes the grids and particles as graph images for the host's own passes, takes force brushes
// and obstacle updates, and reads back particles and diagnostics on demand.
#pragma once

#include "engine/graph/render_graph.h"
#include "liquid/placement.h"
#include "liquid/scene.h"
#include "liquid/types.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace engine::vk {
class Context;
class Image;
}

namespace liquid {

class Simulation;  // the solver itself: internal, not installed

// A mesh obstacle from a host's own geometry, to put in Scene::obstacles before creating the node.
// `vertex_bytes` holds float3 positions (x, y, z as 32-bit floats, m in the mesh's frame) starting
// at byte 0 of each `stride` bytes (stride >= 12: a host's interleaved vertex buffer works as is);
// `indices` are 32-bit, three per triangle, counter-clockwise seen from outside. Vertices at
// identical positions are merged (split normals or texture coordinates are fine). The mesh is
// placed at world = center + rotation * (scale * vertex) and must be closed: every edge shared by
// exactly two triangles of opposite orientation; otherwise a SceneError names `name` and what is
// wrong. At most 4 meshes per scene (each needs a channel of the solver's mesh field).
Obstacle mesh_obstacle(std::span<const std::byte> vertex_bytes, size_t stride, std::span<const uint32_t> indices,
                       glm::vec3 center, const std::string& name = "host mesh");

class LiquidNode {
 public:
  // Throws SceneError when the scene does not fit the device (grid or particle count past its
  // limits), DeviceError when the device lacks a needed format feature or the forced 3D path's
  // feature, and ArgumentError for a LIQUID_3D_PATH that names no path (liquid/error.h).
  LiquidNode(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options = {});
  ~LiquidNode();
  LiquidNode(const LiquidNode&) = delete;
  LiquidNode& operator=(const LiquidNode&) = delete;

  // The scene the node was created from, as it runs it: a mesh's current transform, and a dynamic
  // mesh re-expressed about its centre of mass and principal axes (README, "Bodies that float").
  const Scene& scene() const;
  int dimension() const;
  engine::vk::Context& context() const;
  // The grid: cells per axis (z = 1 in 2D) and the edge of one cell (m).
  glm::ivec3 grid_cells() const;
  float cell_size() const;
  // The 3D path the node chose (LiquidOptions::grid_path; meaningless in 2D).
  GridPath grid_path() const;
  // Frames the GPU may still be running when add_to() is called (views size their uniforms by it).
  uint32_t frames_in_flight() const;

  // Declares `steps` simulation steps on `graph` (the host then compiles and executes it).
  // Advances the host-side clock and particle count: the graph must be executed.
  LiquidImages add_to(engine::graph::RenderGraph& graph, int steps);
  // The scene's steps per frame, and the most one add_to() takes (LiquidOptions::max_steps_per_frame).
  int substeps() const;
  int max_steps_per_frame() const;
  // The length of the next steps (s): the scene's time_step, or with adaptive_time_step the last
  // adapt_time_step()'s (at first, the CFL step of the initial velocities at rest density).
  double time_step() const;
  // With the scene's adaptive_time_step: sizes the following steps by the CFL conditions for the
  // state `d` describes (a diagnose() of the current state), at most the scene's time_step, and
  // returns the step. Without it, returns the fixed step.
  double adapt_time_step(const Diagnostics& d);
  // Sets the following steps' length directly (a host fitting a whole number of steps into its
  // frame). Throws ArgumentError unless 0 < dt <= the scene's time_step and finite.
  void set_time_step(double dt);

  // Where the liquid lies in the host's world (identity until set): what Frame::World positions,
  // velocities and brushes go through, and a compositing renderer's model when a HostView gives
  // none. Gravity stays the scene's, in the liquid's frame (a host tilting the tank and wanting its
  // world's gravity sets RuntimeParameters::gravity to glm::inverse(placement().rotation) * g: the
  // physics stays in the liquid's own metres however large the host draws it). Throws ArgumentError for a non-finite value, a scale that is not
  // positive or a rotation that is not a unit quaternion (to 1e-3).
  void set_placement(const Placement& placement);
  const Placement& placement() const { return placement_; }

  // External forces for the following steps, at most max_force_brushes() of them (the solver's
  // uniform block holds that many; a longer list is refused when the step is declared). In
  // Frame::World a brush's position, radius and acceleration are the world's.
  void set_brushes(std::vector<ForceBrush> brushes, Frame frame = Frame::Liquid);
  static int max_force_brushes();
  // The parameters a host may change while the node runs; they take effect from the next step.
  // Throws ArgumentError on a non-finite gravity, a PIC ratio outside [0, 1] or a negative
  // stiffness. (The energy bound stays the scene's.)
  using RuntimeParameters = liquid::RuntimeParameters;
  RuntimeParameters runtime_parameters() const;
  void set_runtime_parameters(const RuntimeParameters& parameters);
  // The ranges a host's sliders can offer at the present step, every value in them stable: gravity
  // up to max_gravity at `at`'s stiffness, stiffness within its range at `at`'s gravity.
  RuntimeParameterRange runtime_parameter_range(const RuntimeParameters& at) const;
  // Places obstacle `index` (a host-driven obstacle): from now on it moves at `velocity` from
  // `center`, replacing the scene's scripted motion. The set of obstacles and their shapes are
  // fixed when the node is created (the shaders are specialized for them).
  // `frame`: the frame `center` and `velocity` are given in, or the poses are reported in.
  // Throws ArgumentError for a dynamic obstacle (the liquid moves it).
  void set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity, Frame frame = Frame::Liquid);
  // A mesh obstacle's own transform for the following steps (with set_obstacle_pose() for its
  // centre and velocity, once per frame for a host-driven mesh), in the liquid's frame. The mesh is
  // voxelized again in the steps where its placement changed. Its turn moves the liquid: the mesh's
  // surface moves at v + w x (p - center), w the turn from the rotation of the previous call (at an
  // earlier time) to this one, divided by the time between them, the shorter way round; held for
  // as long again, so a mesh the host stops turning stops stirring; zero for the first call. Throws
  // ArgumentError when obstacle `index` is not a mesh, or is a dynamic
  // mesh (the liquid turns it), a scale that is not finite and > 0 or a zero or non-finite rotation.
  void set_mesh_transform(size_t index, glm::quat rotation, float scale);
  // The same with the angular velocity given (rad/s, the liquid's frame), held until the next call:
  // for a host whose turn between frames exceeds half a turn, or that knows its rate exactly.
  void set_mesh_transform(size_t index, glm::quat rotation, float scale, glm::vec3 angular_velocity);
  // Every obstacle's pose at `time` (scripted or set); a dynamic obstacle's is its last known state
  // (latest_bodies(), read_bodies() or diagnose()), whatever `time`.
  std::vector<ObstaclePose> obstacle_poses(double time, Frame frame = Frame::Liquid) const;

  // Dynamic obstacles (rigid bodies the liquid moves; README, "Bodies that float"). Their state lives
  // on the GPU and is integrated there every step, so reading it is the host's choice of cost:
  // A force (N) and torque (N m) of the host's, through the body's centre, added every following
  // step until changed (zero to stop). Throws ArgumentError unless obstacle `index` is
  // dynamic and the values finite.
  void set_body_force(size_t index, glm::vec3 force, glm::vec3 torque = glm::vec3(0.0f));
  // Blocking read (own submission; call when no frame of this node is in flight): the state after
  // the last step declared.
  std::vector<BodyState> read_bodies();
  // Without waiting: every add_to() copies the state at the end of its frame into a host buffer,
  // and this returns the newest copy whose frame has completed by the LiquidOptions contract, i.e.
  // the frame declared frames_in_flight add_to() calls ago (one frame late with one frame in flight).
  std::vector<BodyState> latest_bodies();

  int active_particles() const;
  int step_count() const;
  double time() const;

  // Blocking reads (own submission): call when no frame of this node is in flight. The grids and
  // diagnostics are the liquid's frame's; particles are reported in `frame`.
  ParticleSnapshot read_particles(Frame frame = Frame::Liquid);
  // The grids, cell (x, y, z) at x + nx (y + ny z) on every path.
  std::vector<float> read_density_ratio();
  std::vector<glm::vec4> read_splat();
  std::vector<glm::vec4> read_grid_velocity();
  // Diagnostics of the current state; throws SimulationError when the state is unstable.
  Diagnostics diagnose();
  // The same from particles the host already read back (read_particles()), saving a download.
  Diagnostics diagnose(const ParticleSnapshot& particles);
  double energy_bound() const;

  // Adds a splat and a grid pass of the particles in `images` (what add_to() returned on this
  // graph, possibly for 0 steps) with a zero time step, and returns the new grids: the density and
  // grid velocity of the state as it is now, where add_to()'s come from the last step's splat,
  // taken before its particle update. Exports use it so every file of a frame holds one instant;
  // the particles, clock and counts are left as they are.
  LiquidImages add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images);

  // The whole state between steps (liquid::Checkpoint). Blocking read: call when no frame of this
  // node is in flight.
  using Checkpoint = liquid::Checkpoint;
  Checkpoint save_checkpoint();
  // Throws ArgumentError when the checkpoint's sizes (texture, emitters, obstacles) do not
  // match this node's scene.
  void restore_checkpoint(const Checkpoint& checkpoint);

  // The persistent rho / rho0 grid (R16_SFLOAT: a 3D image in 3D, or the 2D atlas of its slices on
  // the atlas path; a 2D image in 2D), for a host to sample outside the graph, with no copy. After
  // a graph that declared steps has executed, it holds the last step's density, in the layout and
  // after the last access its sync_state() gives. A host using it waits on that state with its own
  // barrier and records where it leaves the image in sync_state(), as for its own imported images;
  // the node's next graph starts from there. Sample it through sampled_view(); never write it.
  engine::vk::Image& density_image();


 private:
  // The solver inside, for the library's own renderer, tools and tests (simulation_of() in the
  // internal, uninstalled liquid/solver/simulation.h).
  friend Simulation& simulation_of(LiquidNode& node);
  friend const Simulation& simulation_of(const LiquidNode& node);
  std::unique_ptr<Simulation> simulation_;
  Placement placement_;
};

}  // namespace liquid
