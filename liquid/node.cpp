// The public LiquidNode forwards to the Simulation it owns (liquid/solver/simulation.h), so the
// public header names no internal type.
#include "liquid/node.h"

#include "liquid/physics/mesh.h"
#include "liquid/physics/time_step.h"
#include "liquid/solver/node_view.h"
#include "liquid/solver/simulation.h"
#include "liquid/solver/state.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace liquid {

LiquidNode::LiquidNode(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options)
    : simulation_(std::make_unique<Simulation>(context, scene, options)) {}
LiquidNode::~LiquidNode() = default;

Simulation& simulation_of(LiquidNode& node) { return *node.simulation_; }
const Simulation& simulation_of(const LiquidNode& node) { return *node.simulation_; }

const SimulationSetup& node_setup(const LiquidNode& node) { return simulation_of(node).setup(); }
const GridLayout& node_grid_layout(const LiquidNode& node) { return simulation_of(node).grid_layout(); }
gpu::SolverUniforms node_uniforms(const LiquidNode& node) { return simulation_of(node).current_uniforms(); }
uint64_t node_frames_declared(const LiquidNode& node) { return simulation_of(node).frames_declared(); }

const Scene& LiquidNode::scene() const { return simulation_->scene(); }
int LiquidNode::dimension() const { return simulation_->dimension(); }
engine::vk::Context& LiquidNode::context() const { return simulation_->context(); }
glm::ivec3 LiquidNode::grid_cells() const { return simulation_->setup().grid_cells; }
float LiquidNode::cell_size() const { return simulation_->setup().cell_size; }
GridPath LiquidNode::grid_path() const { return simulation_->grid_layout().path; }
uint32_t LiquidNode::frames_in_flight() const { return simulation_->frames_in_flight(); }

LiquidImages LiquidNode::add_to(engine::graph::RenderGraph& graph, int steps) { return simulation_->add_to(graph, steps); }
int LiquidNode::substeps() const { return simulation_->substeps(); }
int LiquidNode::max_steps_per_frame() const { return simulation_->max_steps_per_frame(); }
double LiquidNode::time_step() const { return simulation_->time_step(); }
double LiquidNode::adapt_time_step(const Diagnostics& d) { return simulation_->adapt_time_step(d); }
void LiquidNode::set_time_step(double dt) { simulation_->set_time_step(dt); }

void LiquidNode::set_placement(const Placement& placement) {
  const glm::quat& q = placement.rotation;
  const bool finite = std::isfinite(placement.scale) && std::isfinite(q.w) && std::isfinite(q.x) &&
                      std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(placement.translation.x) &&
                      std::isfinite(placement.translation.y) && std::isfinite(placement.translation.z);
  if (!finite) throw ArgumentError("liquid: the placement has a non-finite value");
  if (placement.scale <= 0.0f)
    throw ArgumentError("liquid: the placement's scale " + std::to_string(placement.scale) + " is not positive");
  if (std::abs(glm::length(q) - 1.0f) > 1e-3f)
    throw ArgumentError("liquid: the placement's rotation is not a unit quaternion (length " +
                        std::to_string(glm::length(q)) + ")");
  placement_ = placement;
  placement_.rotation = glm::normalize(q);
}

void LiquidNode::set_brushes(std::vector<ForceBrush> brushes, Frame frame) {
  if (frame == Frame::World)
    for (ForceBrush& brush : brushes) {
      brush.position = placement_.point_to_liquid(brush.position);
      brush.radius /= placement_.scale;
      brush.acceleration = placement_.vector_to_liquid(brush.acceleration);
    }
  simulation_->set_brushes(std::move(brushes));
}
int LiquidNode::max_force_brushes() { return gpu::k_max_brushes; }  // shaders/liquid/shared.h
RuntimeParameters LiquidNode::runtime_parameters() const { return simulation_->runtime_parameters(); }
void LiquidNode::set_runtime_parameters(const RuntimeParameters& p) { simulation_->set_runtime_parameters(p); }
RuntimeParameterRange LiquidNode::runtime_parameter_range(const RuntimeParameters& at) const {
  return liquid::runtime_parameter_range(simulation_->setup(), time_step(), at.stiffness, at.gravity);
}
void LiquidNode::set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity, Frame frame) {
  if (frame == Frame::World) {
    center = placement_.point_to_liquid(center);
    velocity = placement_.vector_to_liquid(velocity);
  }
  simulation_->set_obstacle_pose(index, center, velocity);
}
std::vector<ObstaclePose> LiquidNode::obstacle_poses(double time, Frame frame) const {
  std::vector<ObstaclePose> poses = simulation_->obstacle_poses(time);
  if (frame == Frame::World)
    for (ObstaclePose& pose : poses) {
      pose.center = placement_.point_to_world(pose.center);
      pose.velocity = placement_.vector_to_world(pose.velocity);
      pose.orientation = placement_.rotation * pose.orientation;
      pose.angular_velocity = placement_.rotation * pose.angular_velocity;  // rad/s: turned, not scaled
    }
  return poses;
}

void LiquidNode::set_mesh_transform(size_t index, glm::quat rotation, float scale) {
  simulation_->set_mesh_transform(index, rotation, scale);
}

void LiquidNode::set_mesh_transform(size_t index, glm::quat rotation, float scale, glm::vec3 angular_velocity) {
  simulation_->set_mesh_transform(index, rotation, scale, angular_velocity);
}

Obstacle mesh_obstacle(std::span<const std::byte> vertex_bytes, size_t stride, std::span<const uint32_t> indices,
                       glm::vec3 center, const std::string& name) {
  if (stride < 3 * sizeof(float)) throw SceneError(name + ": the vertex stride must be at least 12 bytes");
  Obstacle obstacle;
  obstacle.shape = ObstacleShape::Mesh;
  obstacle.center = center;
  const size_t count = vertex_bytes.size() / stride + (vertex_bytes.size() % stride >= 3 * sizeof(float) ? 1 : 0);
  for (size_t i = 0; i < count; ++i) {
    float xyz[3];
    std::memcpy(xyz, vertex_bytes.data() + i * stride, sizeof(xyz));
    obstacle.mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  obstacle.mesh.indices.assign(indices.begin(), indices.end());
  for (uint32_t i : obstacle.mesh.indices)
    if (i >= count)
      throw SceneError(name + ": index " + std::to_string(i) + " is past the " + std::to_string(count) + " vertices");
  weld_positions(obstacle.mesh);
  if (const std::string problem = mesh_problem(obstacle.mesh); !problem.empty()) throw SceneError(name + ": " + problem);
  return obstacle;
}
void LiquidNode::set_body_force(size_t index, glm::vec3 force, glm::vec3 torque) {
  simulation_->set_body_force(index, force, torque);
}
std::vector<BodyState> LiquidNode::read_bodies() { return simulation_->read_bodies(); }
std::vector<BodyState> LiquidNode::latest_bodies() { return simulation_->latest_bodies(); }

int LiquidNode::active_particles() const { return simulation_->active_particles(); }
int LiquidNode::step_count() const { return simulation_->step_count(); }
double LiquidNode::time() const { return simulation_->time(); }

ParticleSnapshot LiquidNode::read_particles(Frame frame) {
  ParticleSnapshot snapshot = simulation_->read_particles();
  if (frame == Frame::World) {
    // The w components (the particles' own data) stay as they are.
    for (glm::vec4& p : snapshot.positions) p = glm::vec4(placement_.point_to_world(glm::vec3(p)), p.w);
    for (glm::vec4& v : snapshot.velocities) v = glm::vec4(placement_.vector_to_world(glm::vec3(v)), v.w);
  }
  return snapshot;
}
engine::vk::Image& LiquidNode::density_image() { return simulation_->state().density; }
std::vector<float> LiquidNode::read_density_ratio() { return simulation_->read_density_ratio(); }
std::vector<glm::vec4> LiquidNode::read_splat() { return simulation_->read_splat(); }
std::vector<glm::vec4> LiquidNode::read_grid_velocity() { return simulation_->read_grid_velocity(); }
Diagnostics LiquidNode::diagnose() { return simulation_->diagnose(); }
Diagnostics LiquidNode::diagnose(const ParticleSnapshot& particles) { return simulation_->diagnose(particles); }
double LiquidNode::energy_bound() const { return simulation_->energy_bound(); }

LiquidImages LiquidNode::add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images) {
  return simulation_->add_grids_to(graph, images);
}
Checkpoint LiquidNode::save_checkpoint() { return simulation_->save_checkpoint(); }
void LiquidNode::restore_checkpoint(const Checkpoint& checkpoint) { simulation_->restore_checkpoint(checkpoint); }

}  // namespace liquid
