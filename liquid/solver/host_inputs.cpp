#include "liquid/solver/host_inputs.h"

#include "liquid/physics/obstacles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace liquid {

HostInputs::HostInputs(Scene& scene, const SimulationSetup& setup)
    : scene_(scene),
      setup_(setup),
      emitted_(scene.emitters.size(), 0),
      pose_overrides_(scene.obstacles.size()),
      mesh_turns_(scene.obstacles.size()),
      body_pushes_(scene.obstacles.size()) {}

void HostInputs::set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity, double now) {
  if (index >= pose_overrides_.size())
    throw ArgumentError("liquid: obstacle " + std::to_string(index) + " does not exist");
  if (scene_.obstacles[index].dynamic)
    throw ArgumentError("liquid: obstacle " + std::to_string(index) +
                        " is dynamic: the liquid moves it (set_body_force pushes it)");
  pose_overrides_[index] = PoseOverride{center, velocity, now};
}

void HostInputs::set_mesh_transform(size_t index, glm::quat rotation, float scale,
                                    std::optional<glm::vec3> angular_velocity, double now) {
  if (index >= scene_.obstacles.size() || scene_.obstacles[index].shape != ObstacleShape::Mesh)
    throw ArgumentError("liquid: obstacle " + std::to_string(index) + " is not a mesh");
  if (scene_.obstacles[index].dynamic)
    throw ArgumentError("liquid: obstacle " + std::to_string(index) + " is a dynamic mesh: the liquid turns it");
  if (!(scale > 0.0f && std::isfinite(scale))) throw ArgumentError("liquid: a mesh's scale must be finite and > 0");
  if (!(std::isfinite(glm::length(rotation)) && glm::length(rotation) > 0.0f))
    throw ArgumentError("liquid: a mesh's rotation must be a finite, nonzero quaternion");
  if (angular_velocity && !(std::isfinite(angular_velocity->x) && std::isfinite(angular_velocity->y) &&
                            std::isfinite(angular_velocity->z)))
    throw ArgumentError("liquid: a mesh's angular velocity must be finite");
  rotation = glm::normalize(rotation);
  // The turn is measured from the rotation in effect at the last call made at an earlier time (or
  // the scene's, the first time): calls at one time (several in a frame) correct each other, and
  // the turn between two frames' calls is the one the host made over that interval.
  std::optional<MeshTurn>& turn = mesh_turns_[index];
  if (!turn) {
    const ObstaclePose current = obstacle_poses(now, {})[index];  // not dynamic: no body state needed
    turn = MeshTurn{current.orientation, now, current.orientation, now};
  } else if (now > turn->set_at) {
    turn->from = turn->rotation;
    turn->from_time = turn->set_at;
  }
  turn->rotation = rotation;
  turn->set_at = now;
  if (angular_velocity) {  // the host's: held until its next call
    turn->angular_velocity = *angular_velocity;
    turn->until = INFINITY;
  } else {  // held as long as the turn took, so a mesh the host stops turning stops stirring
    turn->angular_velocity = turn_rate(turn->from, rotation, now - turn->from_time);
    turn->until = now + (now - turn->from_time);
  }
  scene_.obstacles[index].mesh.rotation = rotation;
  scene_.obstacles[index].mesh.scale = scale;
}

size_t HostInputs::dynamic_obstacle(size_t index) const {
  if (index >= scene_.obstacles.size()) throw ArgumentError("liquid: obstacle " + std::to_string(index) + " does not exist");
  if (!scene_.obstacles[index].dynamic)
    throw ArgumentError("liquid: obstacle " + std::to_string(index) + " is not dynamic");
  return index;
}

void HostInputs::set_body_force(size_t index, glm::vec3 force, glm::vec3 torque) {
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(force) || !finite(torque)) throw ArgumentError("liquid: a body's force and torque must be finite");
  body_pushes_[dynamic_obstacle(index)] = {force, torque};
}

std::vector<ObstaclePose> HostInputs::obstacle_poses(double time, const std::vector<BodyState>& bodies) const {
  std::vector<ObstaclePose> poses;
  for (size_t i = 0; i < scene_.obstacles.size(); ++i) {
    const Obstacle& obstacle = scene_.obstacles[i];
    ObstaclePose pose = scripted_pose(obstacle, time);
    if (const auto& o = pose_overrides_[i]) {  // the host's centre and velocity; the scripted spin goes on
      pose.center = o->center + o->velocity * float(time - o->since);
      pose.velocity = o->velocity;
    }
    if (const auto& turn = mesh_turns_[i]) {  // the host's turn of a mesh
      pose.orientation = turn->rotation;
      // Steps end a little past a frame's nominal time in float; a millionth of the interval covers them.
      const double slack = 1e-6 * std::max(turn->until - turn->set_at, 0.0) + 1e-9;
      pose.angular_velocity = time <= turn->until + slack ? turn->angular_velocity : glm::vec3(0.0f);
    }
    poses.push_back(pose);
  }
  for (const BodyState& b : bodies) poses[size_t(b.obstacle)] = b.pose;  // the last known state
  return poses;
}

StepInputs HostInputs::step(double end_time, float dt, int active, const std::vector<BodyState>& bodies) {
  StepInputs step = at(end_time, active, bodies);
  step.dt = dt;
  step.body_pushes = body_pushes_;
  // Emitters (the paper's jet): this step's new particles take the next texels in order.
  int next_index = active;
  for (size_t e = 0; e < scene_.emitters.size(); ++e) {
    const int total = emitted_by(scene_.emitters[e], setup_.dimension, setup_.particle_spacing, end_time);
    const int count = std::min(total - emitted_[e], setup_.capacity - next_index);
    if (count <= 0) continue;
    step.emissions.push_back({int(e), next_index, next_index + count});
    next_index += count;
    emitted_[e] += count;
  }
  step.active_after = next_index;
  return step;
}

StepInputs HostInputs::at(double time, int active, const std::vector<BodyState>& bodies) const {
  StepInputs step;
  step.dt = 0.0f;
  step.active_before = step.active_after = active;
  step.obstacle_poses = obstacle_poses(time, bodies);
  step.brushes = brushes_;
  return step;
}

void HostInputs::save(Checkpoint& c) const {
  c.emitted = emitted_;
  c.poses.clear();
  for (const auto& o : pose_overrides_)
    c.poses.push_back(o ? Checkpoint::Pose{true, o->center, o->velocity, o->since} : Checkpoint::Pose{});
}

void HostInputs::restore(const Checkpoint& c) {
  emitted_ = c.emitted;
  for (size_t i = 0; i < c.poses.size(); ++i) {
    const Checkpoint::Pose& p = c.poses[i];
    pose_overrides_[i] = p.overridden ? std::optional(PoseOverride{p.center, p.velocity, p.since}) : std::nullopt;
  }
}

}  // namespace liquid
