#include "liquid/solver/simulation.h"

#include "engine/graph/transfer.h"
#include "engine/vk/context.h"
#include "liquid/physics/body.h"
#include "liquid/physics/time_step.h"
#include "liquid/scene/format.h"
#include "liquid/solver/active_region.h"
#include "liquid/solver/bodies.h"
#include "liquid/solver/projection_start.h"
#include "liquid/solver/specialization.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
    throw DeviceError("the 3D grid's atlas (" + std::to_string(d.width) + " x " + std::to_string(d.height) +
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

}  // namespace

Simulation::Simulation(engine::vk::Context& context, const Scene& scene, const LiquidOptions& options)
    : context_(context), scene_(solver_scene(scene)), setup_(make_setup(scene_, device_limits(context))),
      frames_in_flight_(options.frames_in_flight), host_(scene_, setup_) {
  const GridLayout layout(setup_.dimension, setup_.grid_cells, grid_path(context, options, setup_.dimension));
  check_atlas_fits(context, layout);
  variant_ = solver_variant(scene_, setup_, layout, options.active_region);
  const SplatFormatChoice format = choose_splat_format(
      scene.splat_format, blendable(context, VK_FORMAT_R32G32B32A32_SFLOAT), blendable(context, VK_FORMAT_R16G16B16A16_SFLOAT));
  splat_format_ = format.format;
  if (options.log) {
    if (setup_.dimension == 3) options.log("liquid: 3D path: " + grid_path_description(layout.path));
    if (format.fell_back) options.log("liquid: the device cannot blend into RGBA32F; the splat uses RGBA16F");
  }
  const std::vector<int32_t> specialization = scene_specialization(scene_, setup_);
  splat_ = make_splat_stage(context, variant_, setup_, splat_format_, specialization);
  grid_ = std::make_unique<GridPass>(context, variant_, specialization);
  if (variant_.splat_adjoint()) pressure_ = std::make_unique<PressurePass>(context, variant_, specialization);
  particle_update_ = std::make_unique<ParticleUpdatePass>(context, variant_, specialization);
  if (variant_.meshes) mesh_field_ = std::make_unique<MeshField>(context, scene_, setup_, layout, specialization);
  body_shapes_ = make_body_shapes(context, scene_, setup_, layout.path);
  if (scene_.whitewater)
    whitewater_ = std::make_unique<WhitewaterPass>(context, variant_, scene_, setup_, specialization);
  if (variant_.bodies) {
    body_force_ = std::make_unique<BodyForcePass>(context, variant_, scene_, setup_, specialization);
    body_integration_ = std::make_unique<BodyIntegrationPass>(context, variant_, specialization);
  }
  const std::vector<glm::vec4> body_texels = initial_body_texels(scene_, setup_);
  bodies_ = decode_bodies(scene_, setup_.dimension, body_texels);
  state_ = std::make_unique<LiquidState>(context, setup_, layout, splat_format_, body_texels, variant_.affine_textures());
  if (engine::vk::Image* p = projection_pressure()) {  // its first guess: still water's (projection_start.h)
    const std::vector<float> start = hydrostatic_projection_start(setup_, layout);
    engine::graph::upload_image(context, *p, std::as_bytes(std::span(start)));
  }
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
  body_readbacks_.resize(options.frames_in_flight + 1);
}

Simulation::~Simulation() = default;

void Simulation::set_runtime_parameters(const RuntimeParameters& p) {
  if (!std::isfinite(p.gravity.x) || !std::isfinite(p.gravity.y) || !std::isfinite(p.gravity.z))
    throw ArgumentError("liquid: gravity must be finite");
  if (!(p.pic_ratio >= 0.0f && p.pic_ratio <= 1.0f)) throw ArgumentError("liquid: pic_ratio must be in [0, 1]");
  if (!(p.stiffness >= 0.0f && std::isfinite(p.stiffness))) throw ArgumentError("liquid: stiffness must be >= 0");
  setup_.gravity = p.gravity;
  setup_.pic_ratio = p.pic_ratio;
  setup_.stiffness = p.stiffness;
}

gpu::SolverUniforms Simulation::uniforms_for(const StepInputs& step) const {
  gpu::SolverUniforms u = make_uniforms(scene_, setup_, step);
  u.atlas_columns = variant_.layout.tiles.x;
  u.atlas_rows = variant_.layout.tiles.y;
  u.active_region_margin_cells = active_region_margin_cells(setup_, variant_.projection());
  return u;
}

gpu::SolverUniforms Simulation::current_uniforms() const {
  StepInputs inputs;
  inputs.obstacle_poses = obstacle_poses(time_);
  return uniforms_for(inputs);
}

void Simulation::add_grid_passes(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& slice,
                                 StepImages& step, bool stepping) const {
  splat_->add_to(graph, slice, step, active_);
  if (pressure_) pressure_->add_to(graph, slice, step, stepping);
  grid_->add_to(graph, slice, step);
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
    throw ArgumentError("liquid: " + std::to_string(steps) + " steps in one frame, at most " +
                        std::to_string(max_steps_per_frame_) + " (LiquidOptions::max_steps_per_frame)");
  uniforms_->begin_frame();
  ++frames_declared_;
  LiquidState& s = *state_;
  const auto import = [&graph](engine::vk::Image& image) { return graph.import_image(image.name(), image); };
  StepImages step;
  const auto particles = [&](int pair) {
    ParticleImages images{import(s.positions[pair]), import(s.velocities[pair])};
    for (size_t a = 0; a < s.affine[pair].size(); ++a) images.affine[a] = import(s.affine[pair][a]);
    return images;
  };
  step.particles = particles(s.current);
  step.particle_targets = particles(1 - s.current);
  step.splat = import(s.splat);
  step.grids = {import(s.grid_velocity), import(s.density), grid_->create_correction(graph)};
  if (pressure_) step.pressure = pressure_->create_images(graph);
  step.bodies = import(s.bodies[s.body_current]);
  step.body_targets = import(s.bodies[1 - s.body_current]);
  collect_body_readbacks();
  if (mesh_field_) step.mesh_field = mesh_field_->import(graph);
  body_shapes_handle_ = import(body_shapes_);
  step.body_shapes = body_shapes_handle_;
  check_step_images(step, variant_);
  WhitewaterPass::Frame whitewater;
  if (whitewater_) whitewater = whitewater_->import(graph);

  const float dt = float(time_step_);
  for (int k = 0; k < steps; ++k) {
    const double t1 = time_ + dt;
    const StepInputs inputs = host_.step(t1, dt, active_, bodies_);
    const engine::vk::UniformSlice slice = uniforms_->push(uniforms_for(inputs));

    // The meshes at the end of the step, where the uniforms place every obstacle.
    step.mesh_field = update_mesh_field(graph, slice, inputs.obstacle_poses, step.mesh_field);
    add_grid_passes(graph, slice, step);
    if (body_integration_) {
      // The liquid's pressure on the bodies at the pose the grid pass used, then their step; the
      // particle pass keeps particles out of where they are at its end.
      body_integration_->add_to(graph, slice, step, body_force_->add_to(graph, slice, step, active_));
      s.body_current = 1 - s.body_current;
    }
    particle_update_->add_to(graph, slice, step, inputs.active_after);
    s.current = 1 - s.current;
    if (whitewater_) whitewater_->add_to(graph, slice, step, whitewater, t1, dt, step_);
    active_ = inputs.active_after;
    time_ = t1;
    ++step_;
  }
  if (body_integration_) {  // for latest_bodies(), frames_in_flight frames from now
    BodyReadback& slot = body_readbacks_[frames_declared_ % body_readbacks_.size()];
    slot.frame = frames_declared_;
    slot.readback = engine::graph::add_readback(graph, step.bodies, "liquid.bodies_readback");
  }
  affine_handles_ = step.particles.affine;
  return {step.particles.positions, step.particles.velocities, step.splat, step.grids.velocity, step.grids.density,
          step.bodies, step.mesh_field, whitewater.latest.positions, whitewater.latest.velocities};
}

std::vector<WhitewaterParticle> Simulation::read_whitewater() {
  return whitewater_ ? whitewater_->read(time_) : std::vector<WhitewaterParticle>{};
}

int Simulation::whitewater_capacity() const {
  return whitewater_ ? whitewater_->texture_size().x * whitewater_->texture_size().y : 0;
}

LiquidImages Simulation::add_grids_to(engine::graph::RenderGraph& graph, const LiquidImages& images) {
  grid_uniforms_->begin_frame();
  // dt 0: the grid pass then leaves the splatted velocity unaccelerated.
  const StepInputs inputs = host_.at(time_, active_, bodies_);
  const engine::vk::UniformSlice slice = grid_uniforms_->push(uniforms_for(inputs));
  // The images add_to() declared in this graph (a second import of the mesh field would lose its state).
  if (mesh_field_ && !images.mesh_field.valid())
    throw UsageError("liquid: add_grids_to needs the images of add_to()");
  StepImages step;
  step.particles = {images.positions, images.velocities, affine_handles_};
  step.splat = images.splat;
  step.grids = {images.grid_velocity, images.density, grid_->create_correction(graph)};
  if (pressure_) step.pressure = pressure_->create_images(graph);
  step.bodies = images.bodies;
  step.body_shapes = body_shapes_handle_;
  step.mesh_field = update_mesh_field(graph, slice, inputs.obstacle_poses, images.mesh_field);
  add_grid_passes(graph, slice, step, false);
  return {images.positions,
          images.velocities,
          step.splat,
          step.grids.velocity,
          step.grids.density,
          images.bodies,
          step.mesh_field,
          images.whitewater_positions,
          images.whitewater_velocities};
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
    throw ArgumentError("liquid: time step " + std::to_string(dt) + " s must be in (0, " +
                        std::to_string(setup_.time_step) + "] s (the scene's time_step)");
  time_step_ = dt;
}

}  // namespace liquid
