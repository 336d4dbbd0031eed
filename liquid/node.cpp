// The public LiquidNode forwards to the Simulation it owns (liquid/solver/simulation.h), so the
// public header names no internal type.
#include "liquid/node.h"

#include "liquid/solver/simulation.h"

namespace liquid {

LiquidNode::LiquidNode(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options)
    : simulation_(std::make_unique<Simulation>(context, scene, options)) {}
LiquidNode::~LiquidNode() = default;

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

void LiquidNode::set_brushes(std::vector<ForceBrush> brushes) { simulation_->set_brushes(std::move(brushes)); }
int LiquidNode::max_force_brushes() { return gpu::k_max_brushes; }  // shaders/liquid/shared.h
RuntimeParameters LiquidNode::runtime_parameters() const { return simulation_->runtime_parameters(); }
void LiquidNode::set_runtime_parameters(const RuntimeParameters& p) { simulation_->set_runtime_parameters(p); }
void LiquidNode::set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity) {
  simulation_->set_obstacle_pose(index, center, velocity);
}
std::vector<ObstaclePose> LiquidNode::obstacle_poses(double time) const { return simulation_->obstacle_poses(time); }
void LiquidNode::set_body_force(size_t index, glm::vec3 force, glm::vec3 torque) {
  simulation_->set_body_force(index, force, torque);
}
std::vector<BodyState> LiquidNode::read_bodies() { return simulation_->read_bodies(); }
std::vector<BodyState> LiquidNode::latest_bodies() { return simulation_->latest_bodies(); }

int LiquidNode::active_particles() const { return simulation_->active_particles(); }
int LiquidNode::step_count() const { return simulation_->step_count(); }
double LiquidNode::time() const { return simulation_->time(); }

ParticleSnapshot LiquidNode::read_particles() { return simulation_->read_particles(); }
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
