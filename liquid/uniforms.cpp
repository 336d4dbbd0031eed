#include "liquid/uniforms.h"

#include <algorithm>
#include <cmath>

#include <stdexcept>
#include <string>

namespace liquid {

void require_at_most(size_t count, int limit, const char* what) {
  if (count > size_t(limit))
    throw std::invalid_argument(std::string("liquid: ") + std::to_string(count) + " " + what + " (at most " +
                                std::to_string(limit) + ")");
}

int obstacle_kind_code(ObstacleShape shape) {
  switch (shape) {
    case ObstacleShape::Sphere: return int(gpu::k_obstacle_sphere);
    case ObstacleShape::Box: return int(gpu::k_obstacle_box);
    case ObstacleShape::Metaballs: return int(gpu::k_obstacle_metaballs);
  }
  return int(gpu::k_obstacle_sphere);
}

float wall_margin(const SimulationSetup& setup) { return setup.scene.wall_margin_cells * setup.cell_size; }

// The artificial obstacle density falls to zero one kernel radius outside the surface.
float obstacle_band(const SimulationSetup& setup) { return setup.scene.kernel_radius_cells * setup.cell_size; }

double kernel_mass_beyond_wall(int dimension, double radius_cells, double distance_cells) {
  if (distance_cells >= radius_cells) return 0.0;
  // A 16-interval midpoint rule: the discretisation the solver's wall correction was validated
  // with. The converged integral shifts the correction by up to a few percent next to the walls and
  // was measured to leave the resting pool (rest_pool_2d) eight times more agitated.
  const double exponent = dimension == 3 ? 4.0 : 3.5;
  constexpr int k_samples = 16;
  double beyond = 0.0, total = 0.0;
  for (int i = 0; i < k_samples; ++i) {
    const double z = -radius_cells + (i + 0.5) * (2.0 * radius_cells / k_samples);
    const double profile = std::pow(std::max(1.0 - z * z / (radius_cells * radius_cells), 0.0), exponent);
    total += profile;
    if (z > distance_cells) beyond += profile;
  }
  return beyond / total;
}

gpu::SolverUniforms make_uniforms(const SimulationSetup& setup, const StepInputs& step) {
  const Scene& scene = setup.scene;
  require_at_most(scene.obstacles.size(), gpu::k_max_obstacles, "obstacles");
  require_at_most(scene.ground.size(), gpu::k_max_ground, "ground hills");
  require_at_most(step.brushes.size(), gpu::k_max_brushes, "force brushes");
  require_at_most(step.emissions.size(), gpu::k_max_emitters, "emitters active in one step");

  gpu::SolverUniforms u{};
  u.domain_h = glm::vec4(setup.domain, setup.cell_size);
  u.grid_dim = glm::ivec4(setup.grid_cells, setup.dimension);
  u.gravity_dt = glm::vec4(setup.gravity, step.dt);
  u.pressure = glm::vec4(setup.stiffness, setup.gamma, setup.rest_density, setup.density_scale);
  u.kernel = glm::vec4(scene.kernel_radius_cells, scene.pic_ratio, wall_margin(setup), obstacle_band(setup));
  u.counts = glm::ivec4(setup.particle_texture.x, step.active_before, step.active_after, int(scene.obstacles.size()));
  u.counts2 = glm::ivec4(int(scene.ground.size()), int(step.brushes.size()), int(step.emissions.size()),
                         scene.mode == SimulationMode::ShallowWater ? 1 : 0);
  u.shallow = glm::vec4(scene.rest_depth, 0.0f, 0.0f, 0.0f);
  for (int k = 0; k < 8; ++k)
    u.wall_kernel_beyond[k / 4][k % 4] =
        float(kernel_mass_beyond_wall(setup.dimension, scene.kernel_radius_cells, double(k) + 0.5));

  int ball = 0;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    const ObstaclePose pose = i < step.obstacle_poses.size() ? step.obstacle_poses[i] : ObstaclePose{o.center, {}};
    gpu::Obstacle& g = u.obstacles[i];
    g.center_kind = glm::vec4(pose.center, float(obstacle_kind_code(o.shape)));
    g.velocity = glm::vec4(pose.velocity, 0.0f);
    switch (o.shape) {
      case ObstacleShape::Sphere: g.size = glm::vec4(o.radius, 0, 0, 0); break;
      case ObstacleShape::Box: g.size = glm::vec4(o.half_extent, 0.0f); break;
      case ObstacleShape::Metaballs:
        require_at_most(ball + o.balls.size(), gpu::k_max_balls, "metaballs in all obstacles");
        g.size = glm::vec4(o.threshold, float(ball), float(o.balls.size()), 0.0f);
        for (const Metaball& m : o.balls) u.balls[ball++] = glm::vec4(m.center, m.radius);
        break;
    }
  }
  for (size_t i = 0; i < scene.ground.size(); ++i) {
    const GroundHill& hill = scene.ground[i];
    u.ground[i] = glm::vec4(hill.center, hill.height, hill.width);
  }
  for (size_t i = 0; i < step.brushes.size(); ++i) {
    const ForceBrush& b = step.brushes[i];
    u.brushes[i] = {glm::vec4(b.position, b.radius), glm::vec4(b.acceleration, 0.0f)};
  }
  for (size_t i = 0; i < step.emissions.size(); ++i) {
    const EmissionRange& e = step.emissions[i];
    const Emitter& emitter = scene.emitters.at(size_t(e.emitter));
    u.emitters[i] = {glm::vec4(emitter.position, emitter.radius), glm::vec4(emitter.velocity, 0.0f),
                     glm::ivec4(e.begin, e.end, 0, 0)};
  }
  return u;
}

}  // namespace liquid
