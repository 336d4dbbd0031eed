// Simulation: what a LiquidNode (include/liquid/node.h, the public API) is made of. It owns the
// state textures, the solver's passes and the host-side clock, and adds one step's splat -> grid ->
// particle update to a render graph; the node forwards its public calls here. The library's own
// renderer, tools and tests reach it through simulation_of(node) (below) for what a host never sees:
// the derived setup, the grid layout, the state textures and the solver's uniform block.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/analysis/diagnostics.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/body_force.h"
#include "liquid/solver/body_integration.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/grid.h"
#include "liquid/solver/host_inputs.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/particle_update.h"
#include "liquid/solver/pressure.h"
#include "liquid/solver/splat_stage.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid/solver/variant.h"
#include "liquid/solver/whitewater.h"
#include "liquid/types.h"
#include "liquid/node.h"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace engine::vk {
class Context;
}

namespace liquid {

class Simulation {
 public:
  // The calls LiquidNode forwards, documented once, in include/liquid/node.h.
  Simulation(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options = {});
  ~Simulation();
  const Scene& scene() const { return scene_; }
  int dimension() const { return setup_.dimension; }
  engine::vk::Context& context() const { return context_; }
  uint32_t frames_in_flight() const { return frames_in_flight_; }
  LiquidImages add_to(engine::graph::RenderGraph& graph, int steps);
  int substeps() const { return scene_.substeps; }
  int max_steps_per_frame() const { return max_steps_per_frame_; }
  double time_step() const { return time_step_; }
  double adapt_time_step(const Diagnostics& d);  // by liquid/physics/time_step.h's CFL conditions
  void set_time_step(double dt);
  void set_brushes(std::vector<ForceBrush> brushes) { host_.set_brushes(std::move(brushes)); }
  const std::vector<ForceBrush>& brushes() const { return host_.brushes(); }
  RuntimeParameters runtime_parameters() const { return {setup_.gravity, setup_.pic_ratio, setup_.stiffness}; }
  void set_runtime_parameters(const RuntimeParameters& parameters);
  void set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity) {
    host_.set_obstacle_pose(index, center, velocity, time_);
  }
  void set_mesh_transform(size_t index, glm::quat rotation, float scale,
                          std::optional<glm::vec3> angular_velocity = std::nullopt) {
    host_.set_mesh_transform(index, rotation, scale, angular_velocity, time_);
  }
  std::vector<ObstaclePose> obstacle_poses(double time) const { return host_.obstacle_poses(time, bodies_); }
  void set_body_force(size_t index, glm::vec3 force, glm::vec3 torque) { host_.set_body_force(index, force, torque); }
  std::vector<BodyState> read_bodies();
  std::vector<BodyState> latest_bodies();
  int active_particles() const { return active_; }
  int step_count() const { return step_; }
  double time() const { return time_; }
  ParticleSnapshot read_particles();
  std::vector<float> read_density_ratio();
  std::vector<glm::vec4> read_splat();
  std::vector<glm::vec4> read_grid_velocity();
  // The live secondary particles (Scene::whitewater; none without it), blocking.
  std::vector<WhitewaterParticle> read_whitewater();
  // Slots for secondary particles (0 without whitewater).
  int whitewater_capacity() const;
  Diagnostics diagnose();
  Diagnostics diagnose(const ParticleSnapshot& particles);
  double energy_bound() const { return energy_bound_; }
  LiquidImages add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images);
  Checkpoint save_checkpoint();
  void restore_checkpoint(const Checkpoint& checkpoint);

  // What only the library's own code sees. The solver parameters derived from the scene:
  // The dynamic meshes' distance texture (tests read it back).
  engine::vk::Image& body_shapes() { return body_shapes_; }
  const SimulationSetup& setup() const { return setup_; }
  // How the grids are stored (3D: images or atlases, liquid/solver/grid_layout.h) and the splat's format.
  const GridLayout& grid_layout() const { return variant_.layout; }
  VkFormat splat_format() const { return splat_format_; }
  // The solver's uniform block for the current state with no step in progress: what the views
  // read (obstacle poses at the node's time).
  gpu::SolverUniforms current_uniforms() const;
  // How many frames add_to() has declared: the views start their uniform space once per frame.
  uint64_t frames_declared() const { return frames_declared_; }
  // The state textures (particles, splat, grids).
  LiquidState& state() { return *state_; }
  // The mesh obstacles' field (null without meshes).
  MeshField* mesh_field() { return mesh_field_.get(); }

 private:
  // Refuses a checkpoint whose values no run reaches (ArgumentError naming the value).
  void check_checkpoint_values(const Checkpoint& checkpoint) const;
  // The pressure projection's kept solution (null without) and its float count (0 without).
  engine::vk::Image* projection_pressure() const;
  size_t projection_values() const;
  // The step's splat, pressure and grid passes (the splat-adjoint pressure's when the variant has it).
  // `stepping` false: the grids for a view at the current time (dt 0), which change no state.
  void add_grid_passes(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice, StepImages& step,
                       bool stepping = true) const;
  // Keeps the newest per-frame read-back of the body state that has completed (latest_bodies()).
  void collect_body_readbacks();
  // The mesh field for obstacles at `poses` (voxelized again when a mesh moved); invalid without meshes.
  ImageHandle update_mesh_field(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice,
                                const std::vector<ObstaclePose>& poses, ImageHandle field);
  // make_uniforms() with the grid layout's atlas tiles.
  gpu::SolverUniforms uniforms_for(const StepInputs& step) const;

  engine::vk::Context& context_;
  Scene scene_;
  SimulationSetup setup_;
  SolverVariant variant_;
  VkFormat splat_format_ = VK_FORMAT_UNDEFINED;
  uint32_t frames_in_flight_ = 2;
  std::unique_ptr<SplatStage> splat_;  // with the active region, unless LiquidOptions::active_region is off
  std::unique_ptr<GridPass> grid_;
  std::unique_ptr<PressurePass> pressure_;  // only with the splat-adjoint pressure
  std::unique_ptr<ParticleUpdatePass> particle_update_;
  std::unique_ptr<BodyForcePass> body_force_;              // only with dynamic obstacles
  std::unique_ptr<BodyIntegrationPass> body_integration_;
  std::unique_ptr<MeshField> mesh_field_;  // only with static mesh obstacles
  std::unique_ptr<WhitewaterPass> whitewater_;  // only with Scene::whitewater
  // The dynamic meshes' distance in their own frames (liquid/solver/body_shapes.h; 1 x 1 x 1
  // without them), and its handle in the graph add_to() last declared (add_grids_to() reads it too).
  engine::vk::Image body_shapes_;
  ImageHandle body_shapes_handle_;
  // The latest particles' C_p (the affine transfer) in the graph add_to() last declared, for
  // add_grids_to()'s splat.
  std::array<ImageHandle, 3> affine_handles_{};
  std::unique_ptr<LiquidState> state_;
  std::unique_ptr<engine::vk::UniformArena> uniforms_;
  std::unique_ptr<engine::vk::UniformArena> grid_uniforms_;  // add_grids_to()'s block, one per frame
  int max_steps_per_frame_ = 0;
  uint64_t frames_declared_ = 0;
  double energy_bound_ = 0.0;

  int active_ = 0;
  int step_ = 0;
  double time_ = 0.0;
  double time_step_ = 0.0;  // s, the next step's
  HostInputs host_;  // on scene_ and setup_
  // The dynamic obstacles' state as last known on the host (a blocking read, or the newest
  // completed per-frame read-back): what the views draw and obstacle_poses() reports for them.
  std::vector<BodyState> bodies_;
  struct BodyReadback {
    uint64_t frame = 0;  // frames_declared_ of the frame that copied it
    engine::graph::Readback readback;
  };
  std::vector<BodyReadback> body_readbacks_;  // one per frame slot
};

// A node's solver: LiquidNode keeps it private, and this header is neither installed nor reachable
// from the public ones (node.cpp defines these).
Simulation& simulation_of(LiquidNode& node);
const Simulation& simulation_of(const LiquidNode& node);

}  // namespace liquid
