// LiquidNode: the one entry point a host engine uses. Created from a scene, it adds the solver's
// passes (splat -> grid -> particle update, per step) to the host's render graph each frame,
// exposes the grids and particles as graph images for the host's own passes, takes force brushes
// and obstacle updates, and reads back particles and diagnostics on demand.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/diagnostics.h"
#include "liquid/scene.h"
#include "liquid/setup.h"
#include "liquid/solver/grid.h"
#include "liquid/solver/particle_update.h"
#include "liquid/solver/pressure.h"
#include "liquid/solver/splat.h"
#include "liquid/state.h"
#include "liquid/types.h"
#include "liquid/uniforms.h"

#include <memory>
#include <optional>
#include <vector>

namespace engine::vk {
class Context;
}

namespace liquid {

class LiquidNode {
 public:
  // Throws SceneError when the scene does not fit the device (grid or particle count past its
  // limits), std::runtime_error when the device lacks a needed format feature or the forced 3D
  // path's feature, and std::invalid_argument for a LIQUID_3D_PATH that names no path.
  LiquidNode(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options = {});
  ~LiquidNode();

  // The scene the node was created from, and the solver parameters derived from it.
  const Scene& scene() const { return scene_; }
  const SimulationSetup& setup() const { return setup_; }
  int dimension() const { return setup_.dimension; }
  engine::vk::Context& context() const { return context_; }
  // How the grids are stored (3D: images or atlases, liquid/grid_layout.h) and the splat's format.
  const GridLayout& grid_layout() const { return layout_; }
  VkFormat splat_format() const { return splat_format_; }
  // Frames the GPU may still be running when add_to() is called (views size their uniforms by it).
  uint32_t frames_in_flight() const { return frames_in_flight_; }

  // Declares `steps` simulation steps on `graph` (the host then compiles and executes it).
  // Advances the host-side clock and particle count: the graph must be executed.
  LiquidImages add_to(engine::graph::RenderGraph& graph, int steps);
  // The scene's steps per frame, and the most one add_to() takes (LiquidOptions::max_steps_per_frame).
  int substeps() const { return scene_.substeps; }
  int max_steps_per_frame() const { return max_steps_per_frame_; }
  // The length of the next steps (s): the scene's time_step, or with adaptive_time_step the last
  // adapt_time_step()'s (at first, the CFL step of the initial velocities at rest density).
  double time_step() const { return time_step_; }
  // With the scene's adaptive_time_step: sizes the following steps by the CFL conditions for the
  // state `d` describes (a diagnose() of the current state; liquid/time_step.h), at most the
  // scene's time_step, and returns the step. Without it, returns the fixed step.
  double adapt_time_step(const Diagnostics& d);
  // Sets the following steps' length directly (a host fitting a whole number of steps into its
  // frame). Throws std::invalid_argument unless 0 < dt <= the scene's time_step and finite.
  void set_time_step(double dt);

  // External forces for the following steps (at most LIQUID_MAX_BRUSHES).
  void set_brushes(std::vector<ForceBrush> brushes) { brushes_ = std::move(brushes); }
  // The parameters a host may change while the node runs (an interactive viewer's sliders); they
  // take effect from the next step. Throws std::invalid_argument on a non-finite gravity, a PIC
  // ratio outside [0, 1] or a negative stiffness. (The energy bound stays the scene's.)
  struct RuntimeParameters {
    glm::vec3 gravity{0.0f};  // m/s^2
    float pic_ratio = 0.0f;   // 1 = PIC, 0 = FLIP
    float stiffness = 0.0f;   // k
  };
  RuntimeParameters runtime_parameters() const { return {setup_.gravity, setup_.pic_ratio, setup_.stiffness}; }
  void set_runtime_parameters(const RuntimeParameters& parameters);
  // Places obstacle `index` (a host-driven obstacle): from now on it moves at `velocity` from
  // `center`, replacing the scene's scripted motion. The set of obstacles and their shapes are
  // fixed when the node is created (the shaders are specialized for them).
  void set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity);
  std::vector<ObstaclePose> obstacle_poses(double time) const;
  // The solver's uniform block for the current state with no step in progress: what the views
  // read (obstacle poses at the node's time).
  gpu::SolverUniforms current_uniforms() const;

  int active_particles() const { return active_; }
  int step_count() const { return step_; }
  double time() const { return time_; }

  // Blocking reads (own submission): call when no frame of this node is in flight.
  ParticleSnapshot read_particles();
  // The grids, cell (x, y, z) at x + nx (y + ny z) on every path.
  std::vector<float> read_density_ratio();
  std::vector<glm::vec4> read_splat();
  std::vector<glm::vec4> read_grid_velocity();
  // Diagnostics of the current state; throws SimulationError when the state is unstable.
  Diagnostics diagnose();
  // The same from particles the host already read back (read_particles()), saving a download.
  Diagnostics diagnose(const ParticleSnapshot& particles);
  double energy_bound() const { return energy_bound_; }

  // Adds a splat and a grid pass of the particles in `images` (what add_to() returned on this
  // graph, possibly for 0 steps) with a zero time step, and returns the new grids: the density and
  // grid velocity of the state as it is now, where add_to()'s come from the last step's splat,
  // taken before its particle update. Exports use it so every file of a frame holds one instant;
  // the particles, clock and counts are left as they are.
  LiquidImages add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images);

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
    double time = 0.0;  // s
    double time_step = 0.0;  // s, the next step's (0: the scene's)
    int active = 0;
    std::vector<int> emitted;      // per emitter
    std::vector<Pose> poses;       // per obstacle
    std::vector<glm::vec4> positions, velocities;  // the whole particle textures, inactive texels too
  };
  // Blocking reads (call when no frame of this node is in flight).
  Checkpoint save_checkpoint();
  // Throws std::invalid_argument when the checkpoint's sizes (texture, emitters, obstacles) do not
  // match this node's scene.
  void restore_checkpoint(const Checkpoint& checkpoint);

  LiquidState& state() { return *state_; }

 private:
  // The splat-adjoint pressure's two grid images for one graph (invalid handles without it).
  struct PressureImages {
    ImageHandle pressure, potential;
  };
  PressureImages create_pressure_images(engine::graph::RenderGraph& graph) const;
  // One step's grid pass, after the splat-adjoint pressure passes when the scene uses them.
  GridImages add_grid(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice, ImageHandle splat,
                      const GridImages& grids, PressureImages& pressure) const;
  // make_uniforms() with the grid layout's atlas tiles.
  gpu::SolverUniforms uniforms_for(const StepInputs& step) const;
  // This step's emission ranges, advancing the emitters' counts.
  std::vector<EmissionRange> emit(double end_time, int& next_index);

  engine::vk::Context& context_;
  Scene scene_;
  SimulationSetup setup_;
  GridLayout layout_;
  VkFormat splat_format_ = VK_FORMAT_UNDEFINED;
  uint32_t frames_in_flight_ = 2;
  std::unique_ptr<SplatPass> splat_;
  std::unique_ptr<GridPass> grid_;
  std::unique_ptr<PressurePass> pressure_;  // only with the splat-adjoint pressure
  std::unique_ptr<ParticleUpdatePass> particle_update_;
  std::unique_ptr<LiquidState> state_;
  std::unique_ptr<engine::vk::UniformArena> uniforms_;
  std::unique_ptr<engine::vk::UniformArena> grid_uniforms_;  // add_grids_to()'s block, one per frame
  int max_steps_per_frame_ = 0;
  double energy_bound_ = 0.0;

  int active_ = 0;
  int step_ = 0;
  double time_ = 0.0;
  double time_step_ = 0.0;  // s, the next step's
  std::vector<int> emitted_;  // per emitter
  std::vector<ForceBrush> brushes_;
  struct PoseOverride {
    glm::vec3 center;
    glm::vec3 velocity;
    double since;
  };
  std::vector<std::optional<PoseOverride>> pose_overrides_;
};

}  // namespace liquid
