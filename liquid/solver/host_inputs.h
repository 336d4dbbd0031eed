// What a host changes between steps (LiquidNode's set_obstacle_pose, set_mesh_transform,
// set_body_force and set_brushes) and the emitters' progress: kept on the host and turned into one
// StepInputs per step (liquid/solver/uniforms.h). It works on the Simulation's scene, whose mesh
// obstacles' rotation and scale a host's turn changes (the mesh field voxelizes them from there).
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/uniforms.h"
#include "liquid/types.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <vector>

namespace liquid {

class HostInputs {
 public:
  // `scene` outlives the inputs (the Simulation owns both).
  HostInputs(Scene& scene, const SimulationSetup& setup);

  // The calls LiquidNode forwards (include/liquid/node.h), made at the node's time `now` (s).
  // Each refuses an index or value it cannot take with ArgumentError.
  void set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity, double now);
  void set_mesh_transform(size_t index, glm::quat rotation, float scale, std::optional<glm::vec3> angular_velocity,
                          double now);
  void set_body_force(size_t index, glm::vec3 force, glm::vec3 torque);
  void set_brushes(std::vector<ForceBrush> brushes) { brushes_ = std::move(brushes); }
  const std::vector<ForceBrush>& brushes() const { return brushes_; }

  // Every obstacle's pose at `time`: scripted, or where the host placed or turned it; the dynamic
  // obstacles' at their last known `bodies` state.
  std::vector<ObstaclePose> obstacle_poses(double time, const std::vector<BodyState>& bodies) const;
  // The step of `dt` that ends at `end_time` and starts with `active` particles: its emission (the
  // next texels in order, advancing the emitters' counts), the poses at its end, brushes and pushes.
  StepInputs step(double end_time, float dt, int active, const std::vector<BodyState>& bodies);
  // The inputs of a grid pass at `time` without a step (dt 0: nothing is emitted or accelerated).
  StepInputs at(double time, int active, const std::vector<BodyState>& bodies) const;

  // A checkpoint's host side: the emitters' counts and the poses the host set.
  void save(Checkpoint& checkpoint) const;
  void restore(const Checkpoint& checkpoint);

 private:
  // The index of a dynamic obstacle, or ArgumentError naming it.
  size_t dynamic_obstacle(size_t index) const;

  Scene& scene_;
  const SimulationSetup& setup_;
  std::vector<int> emitted_;  // per emitter
  std::vector<ForceBrush> brushes_;
  struct PoseOverride {
    glm::vec3 center;
    glm::vec3 velocity;
    double since;
  };
  std::vector<std::optional<PoseOverride>> pose_overrides_;
  // A host's turn of a mesh (set_mesh_transform): its rotation, and the angular velocity the liquid
  // sees at its surface, measured from the rotation in effect at the last call made at an earlier
  // time (`from`, at `from_time`) unless the host gave it, and held until `until` (s).
  struct MeshTurn {
    glm::quat rotation;
    double set_at = 0.0;  // s, the latest call's time
    glm::quat from;
    double from_time = 0.0;
    glm::vec3 angular_velocity{0.0f};
    double until = 0.0;
  };
  std::vector<std::optional<MeshTurn>> mesh_turns_;
  std::vector<BodyPush> body_pushes_;  // per obstacle
};

}  // namespace liquid
