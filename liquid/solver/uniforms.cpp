#include "liquid/solver/uniforms.h"

#include "liquid/physics/body.h"
#include "liquid/physics/pic_blend.h"
#include "liquid/solver/body_shapes.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace liquid {

void require_at_most(size_t count, int limit, const char* what) {
  if (count > size_t(limit))
    throw ArgumentError(std::string("liquid: ") + std::to_string(count) + " " + what + " (at most " +
                        std::to_string(limit) + ")");
}

// A shape's value is its code (include/liquid/scene.h).
static_assert(int(ObstacleShape::Sphere) == LIQUID_OBSTACLE_SPHERE && int(ObstacleShape::Box) == LIQUID_OBSTACLE_BOX &&
              int(ObstacleShape::Metaballs) == LIQUID_OBSTACLE_METABALLS && int(ObstacleShape::Mesh) == LIQUID_OBSTACLE_MESH);
static_assert(std::size(k_obstacle_shape_keys) <= size_t(LIQUID_OBSTACLE_SHAPE_MASK) + 1);

int obstacle_code(const Obstacle& obstacle) {
  return int(obstacle.shape) | (obstacle.dynamic ? gpu::k_obstacle_dynamic : 0);
}

gpu::SolverUniforms make_uniforms(const Scene& scene, const SimulationSetup& setup, const StepInputs& step) {
  // The scene's lists were checked when it entered the library (liquid/scene/limits.h); the
  // step's inputs come from the host each step.
  require_at_most(step.brushes.size(), gpu::k_max_brushes, "force brushes");
  require_at_most(step.emissions.size(), gpu::k_max_emitters, "emitters active in one step");

  gpu::SolverUniforms u{};
  u.domain = setup.domain;
  u.cell_size = setup.cell_size;
  u.grid_cells = setup.grid_cells;
  u.particle_texture_width = setup.particle_texture.x;
  u.gravity = setup.gravity;
  u.dt = step.dt;
  u.stiffness = setup.stiffness;
  u.gamma = setup.gamma;
  u.rest_density = setup.rest_density;
  u.density_scale = setup.density_scale;
  u.kernel_radius = setup.kernel_radius_cells;
  u.pic_ratio = float(pic_blend_for_step(setup.pic_ratio, setup.pic_ratio_reference_step, step.dt));
  u.wall_margin = setup.wall_margin;
  u.obstacle_band = setup.obstacle_band;
  u.active_before = step.active_before;
  u.active_after = step.active_after;
  u.brush_count = int(step.brushes.size());
  u.emission_count = int(step.emissions.size());
  u.rest_depth = setup.rest_depth;
  u.position_correction = scene.position_correction;
  u.deposit_density_scale =
      float(double(setup.particle_mass) / (std::pow(double(setup.cell_size), setup.dimension) * setup.rest_density));
  u.atlas_columns = u.atlas_rows = 1;  // one tile; the node sets an atlas's (Simulation::uniforms_for)
  if (setup.wall_share_beyond.size() != size_t(gpu::k_wall_table_size))
    throw std::logic_error("liquid: the setup's wall table has " + std::to_string(setup.wall_share_beyond.size()) +
                                " entries, not " + std::to_string(gpu::k_wall_table_size) + " (make it with make_setup)");
  for (size_t k = 0; k < setup.wall_share_beyond.size(); ++k)
    u.wall_kernel_beyond[k / 4][k % 4] = setup.wall_share_beyond[k];
  for (size_t k = 0; k < std::min(setup.body_share_beyond.size(), setup.wall_share_beyond.size()); ++k)
    u.body_kernel_beyond[k / 4][k % 4] = setup.body_share_beyond[k];
  u.body_images_beyond_walls = setup.splat == SplatMode::Separable ? 1 : 0;

  if (setup.bodies.size() != scene.obstacles.size())
    throw std::logic_error("liquid: the setup has body constants for " + std::to_string(setup.bodies.size()) +
                                " obstacles, the scene has " + std::to_string(scene.obstacles.size()) +
                                " (make it with make_setup)");
  int ball = 0;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    const ObstaclePose pose = i < step.obstacle_poses.size() ? step.obstacle_poses[i] : ObstaclePose{o.center, {}, o.rotation, {}};
    gpu::Obstacle& g = u.obstacles[i];
    g.center = pose.center;
    g.velocity = pose.velocity;
    g.orientation = glm::vec4(pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w);
    g.angular_velocity = pose.angular_velocity;
    if (o.dynamic) {
      gpu::Body& b = u.bodies[i];
      const BodyConstants& constants = setup.bodies.at(i);
      b.mass = constants.mass;
      b.inertia = constants.inertia;
      b.added_mass = constants.added_mass;
      b.added_inertia_ratio = constants.added_inertia_ratio;
      if (i < step.body_pushes.size()) {
        b.external_force = step.body_pushes[i].force;
        b.external_torque = step.body_pushes[i].torque;
      }
    }
    // An analytic shape's parameters: the shaders read those its kind uses.
    g.sphere_radius = o.radius;
    g.box_half_extent = o.half_extent;
    if (o.shape == ObstacleShape::Metaballs) {
      g.metaball_threshold = o.threshold;
      g.first_ball = ball;
      g.ball_count = int(o.balls.size());
      for (const Metaball& m : o.balls) u.balls[ball++] = glm::vec4(m.center, m.radius);
    }
    // A mesh's distance is the mesh field's (liquid/solver/mesh_field.h), or, a body's, the
    // body-shape texture's (liquid/solver/body_shapes.h), whose size it reads here.
    if (o.shape == ObstacleShape::Mesh && o.dynamic) {
      g.sphere_radius = setup.bodies.at(i).shape_half_size;
      g.box_half_extent = setup.bodies.at(i).shape_half_extent;
    }
  }
  for (size_t i = 0; i < scene.ground.size(); ++i) {
    const GroundHill& hill = scene.ground[i];
    u.ground[i] = glm::vec4(hill.center, hill.height, hill.width);
  }
  for (size_t i = 0; i < step.brushes.size(); ++i) {
    const ForceBrush& b = step.brushes[i];
    u.brushes[i].position = b.position;
    u.brushes[i].radius = b.radius;
    u.brushes[i].acceleration = b.acceleration;
  }
  for (size_t i = 0; i < step.emissions.size(); ++i) {
    const EmissionRange& e = step.emissions[i];
    const Emitter& emitter = scene.emitters.at(size_t(e.emitter));
    gpu::EmitterRange& g = u.emitters[i];
    g.position = emitter.position;
    g.radius = emitter.radius;
    g.velocity = emitter.velocity;
    g.first = e.begin;
    g.end = e.end;
  }
  return u;
}

}  // namespace liquid
