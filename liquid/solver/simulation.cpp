#include "liquid/solver/simulation.h"

#include "engine/graph/transfer.h"
#include "engine/vk/context.h"
#include "liquid/physics/body.h"
#include "liquid/physics/obstacles.h"
#include "liquid/physics/time_step.h"
#include "liquid/scene/format.h"
#include "liquid/solver/bodies.h"
#include "liquid/solver/specialization.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace liquid {
namespace {

DeviceLimits device_limits(const engine::vk::Context& context) {
  const auto& l = context.limits();
  return {int(l.maxImageDimension2D), int(l.maxImageDimension3D), int(l.maxFramebufferLayers)};
}

bool blendable(const engine::vk::Context& context, VkFormat format) {
  return context.format_supports(format, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT);
}

// The 3D path: LiquidOptions' or LIQUID_3D_PATH's, else the device's best (2D scenes use none).
GridPath grid_path(const engine::vk::Context& context, const LiquidOptions& options, int dimension) {
  std::optional<GridPath> requested = options.grid_path;
  if (!requested)
    if (const char* env = std::getenv("LIQUID_3D_PATH"); env && *env) requested = parse_grid_path(env, "LIQUID_3D_PATH");
  const GridPathSupport support{context.supports_geometry_shader(), context.supports_vertex_layer_output()};
  if (dimension == 2) return requested.value_or(GridPath::VertexLayer);
  return choose_grid_path(support, requested);
}

// The atlas is one 2D image: both sides within the device's 2D limit.
void check_atlas_fits(const engine::vk::Context& context, const GridLayout& layout) {
  if (!layout.atlas()) return;
  const engine::vk::ImageDesc d = layout.image_desc(VK_FORMAT_R32G32B32A32_SFLOAT, 0);
  const uint32_t limit = context.limits().maxImageDimension2D;
  if (d.width > limit || d.height > limit)
    throw std::runtime_error("the 3D grid's atlas (" + std::to_string(d.width) + " x " + std::to_string(d.height) +
                             " texels) exceeds the device's 2D image limit of " + std::to_string(limit) +
                             "; lower grid_resolution or use another 3D path");
}

// The scene as the solver runs it: a mesh obstacle's rotation is its mesh's (what a host set on the
// mesh), and a dynamic mesh is re-expressed about its centre of mass and principal axes, where its
// rigid body turns (liquid/physics/body.h).
Scene solver_scene(Scene scene) {
  for (Obstacle& o : scene.obstacles) {
    if (o.shape != ObstacleShape::Mesh) continue;
    o.rotation = o.mesh.rotation;
    o = mesh_body_in_principal_frame(o);
  }
  return scene;
}

template <class T>
std::vector<T> as_vector(const std::vector<std::byte>& bytes, size_t count) {
  std::vector<T> out(count);
  // No particles yet (an emitter's first steps): both vectors may be empty, their data() null,
  // which memcpy must not be given even for no bytes.
  if (const size_t size = std::min(bytes.size(), count * sizeof(T)); size > 0) std::memcpy(out.data(), bytes.data(), size);
  return out;
}

}  // namespace

Simulation::Simulation(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options)
    : context_(context), scene_(solver_scene(scene)), setup_(make_setup(scene_, device_limits(context))),
      frames_in_flight_(options.frames_in_flight) {
  layout_ = GridLayout(setup_.dimension, setup_.grid_cells, grid_path(context, options, setup_.dimension));
  check_atlas_fits(context, layout_);
  const SplatFormatChoice format = choose_splat_format(
      scene.splat_format, blendable(context, VK_FORMAT_R32G32B32A32_SFLOAT), blendable(context, VK_FORMAT_R16G16B16A16_SFLOAT));
  splat_format_ = format.format;
  if (options.log) {
    if (setup_.dimension == 3) options.log("liquid: 3D path: " + grid_path_description(layout_.path));
    if (format.fell_back) options.log("liquid: the device cannot blend into RGBA32F; the splat uses RGBA16F");
  }
  const std::vector<int32_t> specialization = scene_specialization(scene_, setup_);
  const bool active_region = options.active_region && setup_.dimension == 3;
  if (active_region) active_region_ = std::make_unique<ActiveRegion>(context, layout_, specialization);
  if (setup_.splat == SplatMode::Separable)
    separable_splat_ =
        std::make_unique<SeparableSplatPass>(context, layout_, splat_format_, specialization, active_region);
  else
    splat_ = std::make_unique<SplatPass>(context, setup_, layout_, splat_format_, specialization);
  const bool meshes = has_mesh_obstacles(scene_);
  grid_ = std::make_unique<GridPass>(context, setup_, layout_, specialization, meshes, active_region);
  if (setup_.splat_adjoint_pressure)
    pressure_ =
        std::make_unique<PressurePass>(context, layout_, setup_.splat, specialization, meshes, active_region);
  particle_update_ = std::make_unique<ParticleUpdatePass>(context, layout_, specialization, meshes);
  if (meshes) mesh_field_ = std::make_unique<MeshField>(context, scene_, setup_, layout_, specialization);
  const bool dynamic = std::any_of(scene.obstacles.begin(), scene.obstacles.end(), [](const Obstacle& o) { return o.dynamic; });
  body_shapes_ = make_body_shapes(context, scene_, setup_, layout_.path);
  if (dynamic) {
    body_force_ = std::make_unique<BodyForcePass>(context, layout_, int(scene.obstacles.size()), setup_.particle_mass,
                                                  specialization);
    body_integration_ = std::make_unique<BodyIntegrationPass>(context, setup_.dimension, specialization);
  }
  const std::vector<glm::vec4> body_texels = initial_body_texels(scene_, setup_);
  bodies_ = decode_bodies(scene_, setup_.dimension, body_texels);
  state_ = std::make_unique<LiquidState>(context, setup_, layout_, splat_format_, body_texels);
  max_steps_per_frame_ = options.max_steps_per_frame > 0 ? options.max_steps_per_frame : scene.substeps;
  uniforms_ = std::make_unique<engine::vk::UniformArena>(
      context, engine::vk::UniformArena::frame_bytes({sizeof(gpu::SolverUniforms)}, max_steps_per_frame_),
      options.frames_in_flight + 1);
  grid_uniforms_ = std::make_unique<engine::vk::UniformArena>(
      context, engine::vk::UniformArena::frame_bytes({sizeof(gpu::SolverUniforms)}), options.frames_in_flight + 1);
  energy_bound_ = kinetic_energy_bound(scene_, setup_, options.energy_bound_factor);
  time_step_ = setup_.time_step;
  if (scene_.adaptive_time_step) {  // the first steps: the initial velocities at rest density
    Diagnostics initial;
    initial.max_density_ratio = 1.0f;
    for (const glm::vec4& v : setup_.velocities) initial.max_speed = std::max(initial.max_speed, glm::length(glm::vec3(v)));
    adapt_time_step(initial);
  }
  active_ = setup_.initial_particles;
  emitted_.assign(scene.emitters.size(), 0);
  pose_overrides_.resize(scene.obstacles.size());
  mesh_turns_.resize(scene.obstacles.size());
  body_pushes_.resize(scene.obstacles.size());
  body_readbacks_.resize(options.frames_in_flight + 1);
}

Simulation::~Simulation() = default;

void Simulation::set_runtime_parameters(const RuntimeParameters& p) {
  if (!std::isfinite(p.gravity.x) || !std::isfinite(p.gravity.y) || !std::isfinite(p.gravity.z))
    throw std::invalid_argument("liquid: gravity must be finite");
  if (!(p.pic_ratio >= 0.0f && p.pic_ratio <= 1.0f)) throw std::invalid_argument("liquid: pic_ratio must be in [0, 1]");
  if (!(p.stiffness >= 0.0f && std::isfinite(p.stiffness))) throw std::invalid_argument("liquid: stiffness must be >= 0");
  setup_.gravity = p.gravity;
  setup_.pic_ratio = p.pic_ratio;
  setup_.stiffness = p.stiffness;
}

void Simulation::set_obstacle_pose(size_t index, glm::vec3 center, glm::vec3 velocity) {
  if (index >= pose_overrides_.size())
    throw std::out_of_range("liquid: obstacle " + std::to_string(index) + " does not exist");
  if (scene_.obstacles[index].dynamic)
    throw std::invalid_argument("liquid: obstacle " + std::to_string(index) +
                                " is dynamic: the liquid moves it (set_body_force pushes it)");
  pose_overrides_[index] = PoseOverride{center, velocity, time_};
}

void Simulation::set_mesh_transform(size_t index, glm::quat rotation, float scale,
                                    std::optional<glm::vec3> angular_velocity) {
  if (index >= scene_.obstacles.size() || scene_.obstacles[index].shape != ObstacleShape::Mesh)
    throw std::out_of_range("liquid: obstacle " + std::to_string(index) + " is not a mesh");
  if (scene_.obstacles[index].dynamic)
    throw std::invalid_argument("liquid: obstacle " + std::to_string(index) + " is a dynamic mesh: the liquid turns it");
  if (!(scale > 0.0f && std::isfinite(scale))) throw std::invalid_argument("liquid: a mesh's scale must be finite and > 0");
  if (!(std::isfinite(glm::length(rotation)) && glm::length(rotation) > 0.0f))
    throw std::invalid_argument("liquid: a mesh's rotation must be a finite, nonzero quaternion");
  if (angular_velocity && !(std::isfinite(angular_velocity->x) && std::isfinite(angular_velocity->y) &&
                            std::isfinite(angular_velocity->z)))
    throw std::invalid_argument("liquid: a mesh's angular velocity must be finite");
  rotation = glm::normalize(rotation);
  // The turn is measured from the rotation in effect at the last call made at an earlier time (or
  // the scene's, the first time): calls at one time (several in a frame) correct each other, and
  // the turn between two frames' calls is the one the host made over that interval.
  std::optional<MeshTurn>& turn = mesh_turns_[index];
  if (!turn) {
    const ObstaclePose now = obstacle_poses(time_)[index];
    turn = MeshTurn{now.orientation, time_, now.orientation, time_};
  } else if (time_ > turn->set_at) {
    turn->from = turn->rotation;
    turn->from_time = turn->set_at;
  }
  turn->rotation = rotation;
  turn->set_at = time_;
  if (angular_velocity) {  // the host's: held until its next call
    turn->angular_velocity = *angular_velocity;
    turn->until = INFINITY;
  } else {  // held as long as the turn took, so a mesh the host stops turning stops stirring
    turn->angular_velocity = turn_rate(turn->from, rotation, time_ - turn->from_time);
    turn->until = time_ + (time_ - turn->from_time);
  }
  scene_.obstacles[index].mesh.rotation = rotation;
  scene_.obstacles[index].mesh.scale = scale;
}

std::vector<ObstaclePose> Simulation::obstacle_poses(double time) const {
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
  for (const BodyState& b : bodies_) poses[size_t(b.obstacle)] = b.pose;  // the last known state
  return poses;
}

size_t Simulation::dynamic_obstacle(size_t index) const {
  if (index >= scene_.obstacles.size()) throw std::out_of_range("liquid: obstacle " + std::to_string(index) + " does not exist");
  if (!scene_.obstacles[index].dynamic)
    throw std::invalid_argument("liquid: obstacle " + std::to_string(index) + " is not dynamic");
  return index;
}

void Simulation::set_body_force(size_t index, glm::vec3 force, glm::vec3 torque) {
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(force) || !finite(torque)) throw std::invalid_argument("liquid: a body's force and torque must be finite");
  body_pushes_[dynamic_obstacle(index)] = {force, torque};
}

std::vector<BodyState> Simulation::read_bodies() {
  if (!body_integration_) return {};
  const auto bytes = engine::graph::download_image(context_, state_->bodies[state_->body_current]);
  const engine::vk::ImageDesc& d = state_->bodies[state_->body_current].desc();
  bodies_ = decode_bodies(scene_, setup_.dimension, as_vector<glm::vec4>(bytes, size_t(d.width) * d.height));
  return bodies_;
}

void Simulation::collect_body_readbacks() {
  // A frame is complete once frames_in_flight later ones have been declared (LiquidOptions).
  const BodyReadback* newest = nullptr;
  for (const BodyReadback& r : body_readbacks_)
    if (r.readback.buffer && r.frame + frames_in_flight_ <= frames_declared_ && (!newest || r.frame > newest->frame))
      newest = &r;
  if (!newest) return;
  const engine::vk::ImageDesc& d = newest->readback.desc;
  const auto bytes = newest->readback.bytes();
  bodies_ = decode_bodies(scene_, setup_.dimension,
                          as_vector<glm::vec4>(std::vector<std::byte>(bytes.begin(), bytes.end()), size_t(d.width) * d.height));
  for (BodyReadback& r : body_readbacks_)
    if (r.frame <= newest->frame) r.readback = {};
}

std::vector<BodyState> Simulation::latest_bodies() {
  collect_body_readbacks();
  return bodies_;
}

gpu::SolverUniforms Simulation::uniforms_for(const StepInputs& step) const {
  gpu::SolverUniforms u = make_uniforms(scene_, setup_, step);
  u.atlas_columns = layout_.tiles.x;
  u.atlas_rows = layout_.tiles.y;
  u.active_region_margin_cells = active_region_margin_cells(setup_);
  return u;
}

gpu::SolverUniforms Simulation::current_uniforms() const {
  StepInputs inputs;
  inputs.obstacle_poses = obstacle_poses(time_);
  return uniforms_for(inputs);
}

std::vector<EmissionRange> Simulation::emit(double end_time, int& next_index) {
  // Emitters (the paper's jet): this step's new particles take the next texels in order.
  std::vector<EmissionRange> ranges;
  for (size_t e = 0; e < scene_.emitters.size(); ++e) {
    const int total = emitted_by(scene_.emitters[e], setup_.dimension, setup_.particle_spacing, end_time);
    const int count = std::min(total - emitted_[e], setup_.capacity - next_index);
    if (count <= 0) continue;
    ranges.push_back({int(e), next_index, next_index + count});
    next_index += count;
    emitted_[e] += count;
  }
  return ranges;
}

Simulation::PressureImages Simulation::create_pressure_images(engine::graph::RenderGraph& graph) const {
  if (!pressure_) return {};
  PressureImages images{graph.create_image("liquid.pressure", pressure_->image_desc()),
                        graph.create_image("liquid.potential", pressure_->image_desc()), {}};
  if (body_force_ && setup_.splat == SplatMode::Separable)  // the body force reads P after the spread
    images.scratch = graph.create_image("liquid.potential_scratch", pressure_->image_desc());
  return images;
}

Simulation::Splat Simulation::add_splat(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice,
                                        const ParticleImages& particles, ImageHandle splat, int active) const {
  // The region's marks: the deposit's (its spreads are trimmed to the region), or the whole splat's.
  auto region_of = [&](ImageHandle marks) { return active_region_ ? active_region_->add_to(graph, slice, marks) : ImageHandle{}; };
  if (!separable_splat_) {
    const ImageHandle out = splat_->add_to(graph, slice, particles, splat, active);
    return {out, region_of(out)};
  }
  const SeparableSplatPass::Deposit deposit = separable_splat_->deposit(graph, slice, particles, splat, active);
  const ImageHandle region = region_of(deposit.lower);
  return {separable_splat_->spread(graph, slice, deposit, splat, region), region};
}

GridImages Simulation::add_grid(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice,
                                const Splat& splat, ImageHandle bodies, ImageHandle body_shapes, const GridImages& grids,
                                PressureImages& pressure, ImageHandle mesh_field) const {
  if (!pressure_) return grid_->add_to(graph, slice, splat.splat, bodies, body_shapes, grids, {}, mesh_field, splat.region);
  const ImageHandle potential = pressure_->add_to(graph, slice, splat.splat, bodies, body_shapes, pressure.pressure,
                                                  pressure.potential, pressure.scratch, mesh_field, splat.region);
  return grid_->add_to(graph, slice, splat.splat, bodies, body_shapes, grids, potential, mesh_field, splat.region);
}

ImageHandle Simulation::update_mesh_field(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice,
                                          const std::vector<ObstaclePose>& poses, ImageHandle field) {
  // A mesh is voxelized (and drawn) at its pose's orientation: the scene's, spun by the script, the
  // host's turn, or a dynamic mesh's last known.
  for (size_t i = 0; i < scene_.obstacles.size(); ++i)
    if (scene_.obstacles[i].shape == ObstacleShape::Mesh) scene_.obstacles[i].mesh.rotation = poses[i].orientation;
  if (!mesh_field_) return {};
  return mesh_field_->update(graph, slice, scene_.obstacles, poses, field);
}

LiquidImages Simulation::add_to(engine::graph::RenderGraph& graph, int steps) {
  if (steps > max_steps_per_frame_)
    throw std::invalid_argument("liquid: " + std::to_string(steps) + " steps in one frame, at most " +
                                std::to_string(max_steps_per_frame_) + " (LiquidOptions::max_steps_per_frame)");
  uniforms_->begin_frame();
  ++frames_declared_;
  LiquidState& s = *state_;
  std::array<ParticleImages, 2> particles;
  for (int i = 0; i < 2; ++i)
    particles[i] = {graph.import_image(s.positions[i].name(), s.positions[i]),
                    graph.import_image(s.velocities[i].name(), s.velocities[i])};
  ImageHandle splat = graph.import_image(s.splat.name(), s.splat);
  GridImages grids{graph.import_image(s.grid_velocity.name(), s.grid_velocity),
                   graph.import_image(s.density.name(), s.density)};
  PressureImages pressure = create_pressure_images(graph);
  std::array<ImageHandle, 2> bodies;
  for (int i = 0; i < 2; ++i) bodies[i] = graph.import_image(s.bodies[i].name(), s.bodies[i]);
  collect_body_readbacks();
  ImageHandle mesh_field = mesh_field_ ? mesh_field_->import(graph) : ImageHandle{};
  body_shapes_handle_ = graph.import_image(body_shapes_.name(), body_shapes_);

  const float dt = float(time_step_);
  for (int k = 0; k < steps; ++k) {
    const double t1 = time_ + dt;
    StepInputs step;
    step.dt = dt;
    step.active_before = active_;
    int next_index = active_;
    step.emissions = emit(t1, next_index);
    step.active_after = next_index;
    step.obstacle_poses = obstacle_poses(t1);
    step.brushes = brushes_;
    step.body_pushes = body_pushes_;
    const engine::vk::UniformSlice slice = uniforms_->push(uniforms_for(step));

    const int cur = s.current, next = 1 - s.current;
    // The meshes at the end of the step, where the uniforms place every obstacle.
    mesh_field = update_mesh_field(graph, slice, step.obstacle_poses, mesh_field);
    const Splat step_splat = add_splat(graph, slice, particles[cur], splat, active_);
    splat = step_splat.splat;
    grids = add_grid(graph, slice, step_splat, bodies[s.body_current], body_shapes_handle_, grids, pressure, mesh_field);
    if (body_integration_) {
      // The liquid's pressure on the bodies at the pose the grid pass used, then their step; the
      // particle pass keeps particles out of where they are at its end.
      std::vector<int> dynamic;
      for (size_t i = 0; i < scene_.obstacles.size(); ++i)
        if (scene_.obstacles[i].dynamic) dynamic.push_back(int(i));
      const BodyForceImages force = body_force_->add_to(graph, slice, splat, pressure.pressure, particles[cur].positions,
                                                        active_, bodies[s.body_current], body_shapes_handle_, dynamic);
      const int body_next = 1 - s.body_current;
      bodies[body_next] = body_integration_->add_to(graph, slice, bodies[s.body_current], force, bodies[body_next]);
      s.body_current = body_next;
    }
    particles[next] = particle_update_->add_to(graph, slice, particles[cur], splat, grids, bodies[s.body_current],
                                               body_shapes_handle_, particles[next], step.active_after, mesh_field);
    s.current = next;
    active_ = step.active_after;
    time_ = t1;
    ++step_;
  }
  if (body_integration_) {  // for latest_bodies(), frames_in_flight frames from now
    BodyReadback& slot = body_readbacks_[frames_declared_ % body_readbacks_.size()];
    slot.frame = frames_declared_;
    slot.readback = engine::graph::add_readback(graph, bodies[s.body_current], "liquid.bodies_readback");
  }
  return {particles[s.current].positions, particles[s.current].velocities, splat, grids.velocity, grids.density,
          bodies[s.body_current], mesh_field};
}

LiquidImages Simulation::add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images) {
  grid_uniforms_->begin_frame();
  StepInputs step;
  step.dt = 0.0f;  // the grid pass then leaves the splatted velocity unaccelerated
  step.active_before = step.active_after = active_;
  step.obstacle_poses = obstacle_poses(time_);
  step.brushes = brushes_;
  const engine::vk::UniformSlice slice = grid_uniforms_->push(uniforms_for(step));
  const ParticleImages particles{images.positions, images.velocities};
  const Splat splat = add_splat(graph, slice, particles, images.splat, active_);
  PressureImages pressure = create_pressure_images(graph);
  // The field add_to() imported into this graph (a second import would lose its state).
  ImageHandle mesh_field = images.mesh_field;
  if (mesh_field_ && !mesh_field.valid()) throw std::invalid_argument("liquid: add_grids_to needs the images of add_to()");
  mesh_field = update_mesh_field(graph, slice, step.obstacle_poses, mesh_field);
  const GridImages grids = add_grid(graph, slice, splat, images.bodies, body_shapes_handle_,
                                    GridImages{images.grid_velocity, images.density}, pressure, mesh_field);
  return {images.positions, images.velocities, splat.splat, grids.velocity, grids.density, images.bodies, mesh_field};
}

Checkpoint Simulation::save_checkpoint() {
  Checkpoint c;
  c.step = step_;
  c.time = time_;
  c.time_step = time_step_;
  c.active = active_;
  c.emitted = emitted_;
  for (const auto& o : pose_overrides_)
    c.poses.push_back(o ? Checkpoint::Pose{true, o->center, o->velocity, o->since} : Checkpoint::Pose{});
  const size_t texels = size_t(setup_.particle_texture.x) * setup_.particle_texture.y;
  c.positions = as_vector<glm::vec4>(engine::graph::download_image(context_, state_->positions[state_->current]), texels);
  c.velocities =
      as_vector<glm::vec4>(engine::graph::download_image(context_, state_->velocities[state_->current]), texels);
  engine::vk::Image& bodies = state_->bodies[state_->body_current];
  c.bodies = as_vector<glm::vec4>(engine::graph::download_image(context_, bodies),
                                  size_t(bodies.desc().width) * bodies.desc().height);
  return c;
}

// Every value a checkpoint carries within what a run can reach, so a damaged or edited one is
// refused naming the value rather than run (a NaN position used to surface as "simulation
// unstable" steps later).
void Simulation::check_checkpoint_values(const Checkpoint& c) const {
  const auto refuse = [](const std::string& what) { throw std::invalid_argument("liquid: the checkpoint's " + what); };
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (c.step < 0) refuse("step count is negative (" + std::to_string(c.step) + ")");
  if (!(std::isfinite(c.time) && c.time >= 0.0)) refuse("time is not a finite time >= 0 s");
  if (!(std::isfinite(c.time_step) && c.time_step >= 0.0 && c.time_step <= double(setup_.time_step) * (1.0 + 1e-6)))
    refuse("time step is not in [0, " + format_number(setup_.time_step) + "] s");
  for (size_t e = 0; e < c.emitted.size(); ++e)
    if (c.emitted[e] < 0 || c.emitted[e] > scene_.emitters[e].capacity)
      refuse("emitter " + std::to_string(e) + " has added " + std::to_string(c.emitted[e]) + " particles, outside [0, " +
             std::to_string(scene_.emitters[e].capacity) + "]");
  for (size_t i = 0; i < c.poses.size(); ++i)
    if (!finite(c.poses[i].center) || !finite(c.poses[i].velocity) || !std::isfinite(c.poses[i].since))
      refuse("obstacle " + std::to_string(i) + " has a non-finite pose");
  for (size_t i = 0; i < c.bodies.size(); ++i)
    if (!finite(glm::vec3(c.bodies[i])) || !std::isfinite(c.bodies[i].w))
      refuse("body state holds a non-finite value (texel " + std::to_string(i) + ")");
  for (int i = 0; i < c.active; ++i) {
    const glm::vec4 p = c.positions[size_t(i)], v = c.velocities[size_t(i)];
    if (!finite(glm::vec3(p)) || !finite(glm::vec3(v)))
      refuse("particle " + std::to_string(i) + " has a non-finite position or velocity");
    for (int a = 0; a < setup_.dimension; ++a)
      if (p[a] < 0.0f || p[a] > setup_.domain[a])
        refuse("particle " + std::to_string(i) + " lies outside the domain (" + format_number(p[a]) + " m on axis " +
               std::to_string(a) + ")");
  }
}

void Simulation::restore_checkpoint(const Checkpoint& c) {
  const size_t texels = size_t(setup_.particle_texture.x) * setup_.particle_texture.y;
  if (c.active < 0 || c.active > setup_.capacity)
    throw std::invalid_argument("liquid: the checkpoint holds " + std::to_string(c.active) +
                                " active particles, outside the scene's capacity of 0 to " + std::to_string(setup_.capacity));
  const engine::vk::ImageDesc& body_desc = state_->bodies[0].desc();
  if (c.positions.size() != texels || c.velocities.size() != texels || c.emitted.size() != emitted_.size() ||
      c.poses.size() != pose_overrides_.size() || c.bodies.size() != size_t(body_desc.width) * body_desc.height)
    throw std::invalid_argument("liquid: the checkpoint does not match this scene (" + std::to_string(c.positions.size()) +
                                " particle texels, " + std::to_string(c.emitted.size()) + " emitters, " +
                                std::to_string(c.poses.size()) + " obstacles; the scene has " + std::to_string(texels) +
                                ", " + std::to_string(emitted_.size()) + ", " + std::to_string(pose_overrides_.size()) + ")");
  check_checkpoint_values(c);
  engine::graph::upload_image(context_, state_->positions[state_->current], std::as_bytes(std::span(c.positions)));
  engine::graph::upload_image(context_, state_->velocities[state_->current], std::as_bytes(std::span(c.velocities)));
  engine::graph::upload_image(context_, state_->bodies[state_->body_current], std::as_bytes(std::span(c.bodies)));
  bodies_ = decode_bodies(scene_, setup_.dimension, c.bodies);
  for (BodyReadback& r : body_readbacks_) r.readback = {};
  step_ = c.step;
  time_ = c.time;
  time_step_ = c.time_step > 0.0 ? c.time_step : double(setup_.time_step);
  active_ = c.active;
  emitted_ = c.emitted;
  for (size_t i = 0; i < c.poses.size(); ++i) {
    const Checkpoint::Pose& p = c.poses[i];
    pose_overrides_[i] = p.overridden ? std::optional(PoseOverride{p.center, p.velocity, p.since}) : std::nullopt;
  }
}

ParticleSnapshot Simulation::read_particles() {
  ParticleSnapshot snapshot;
  snapshot.positions =
      as_vector<glm::vec4>(engine::graph::download_image(context_, state_->positions[state_->current]), size_t(active_));
  snapshot.velocities =
      as_vector<glm::vec4>(engine::graph::download_image(context_, state_->velocities[state_->current]), size_t(active_));
  return snapshot;
}

std::vector<float> Simulation::read_density_ratio() {
  const auto bytes = engine::graph::download_image(context_, state_->density);
  std::vector<float> ratio(bytes.size() / 2);
  const uint16_t* halves = reinterpret_cast<const uint16_t*>(bytes.data());
  for (size_t i = 0; i < ratio.size(); ++i) ratio[i] = glm::unpackHalf1x16(halves[i]);
  return layout_.to_linear(ratio);
}

std::vector<glm::vec4> Simulation::read_splat() {
  const engine::vk::ImageDesc& d = state_->splat.desc();
  const size_t texels = size_t(d.width) * d.height * d.depth_or_layers;
  const auto bytes = engine::graph::download_image(context_, state_->splat);
  if (d.format == VK_FORMAT_R32G32B32A32_SFLOAT) return layout_.to_linear(as_vector<glm::vec4>(bytes, texels));
  std::vector<glm::vec4> out(texels);
  const uint16_t* halves = reinterpret_cast<const uint16_t*>(bytes.data());
  for (size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 4; ++c) out[i][c] = glm::unpackHalf1x16(halves[i * 4 + c]);
  return layout_.to_linear(out);
}

std::vector<glm::vec4> Simulation::read_grid_velocity() {
  const engine::vk::ImageDesc& d = state_->grid_velocity.desc();
  const size_t texels = size_t(d.width) * d.height * d.depth_or_layers;
  return layout_.to_linear(as_vector<glm::vec4>(engine::graph::download_image(context_, state_->grid_velocity), texels));
}

Diagnostics Simulation::diagnose() { return diagnose(read_particles()); }

Diagnostics Simulation::diagnose(const ParticleSnapshot& particles) {
  read_bodies();
  Diagnostics d =
      compute_diagnostics(scene_, setup_, particles, read_density_ratio(), obstacle_poses(time_), step_, time_);
  d.bodies = bodies_;
  d.time_step = time_step_;  // the steps just run took it (adapt_time_step() comes after a diagnosis)
  check_stable(d, energy_bound_);
  return d;
}

double Simulation::adapt_time_step(const Diagnostics& d) {
  if (scene_.adaptive_time_step)
    time_step_ = cfl_time_step(setup_, *scene_.adaptive_time_step, d, double(setup_.time_step));
  return time_step_;
}

void Simulation::set_time_step(double dt) {
  if (!std::isfinite(dt) || dt <= 0.0 || dt > double(setup_.time_step))
    throw std::invalid_argument("liquid: time step " + std::to_string(dt) + " s must be in (0, " +
                                std::to_string(setup_.time_step) + "] s (the scene's time_step)");
  time_step_ = dt;
}

}  // namespace liquid
