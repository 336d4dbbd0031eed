#include "liquid/specialization.h"

#include "liquid/gpu_types.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace liquid {
namespace {

int32_t obstacle_kind(ObstacleShape shape) {
  switch (shape) {
    case ObstacleShape::Sphere: return int32_t(gpu::k_obstacle_sphere);
    case ObstacleShape::Box: return int32_t(gpu::k_obstacle_box);
    case ObstacleShape::Metaballs: return int32_t(gpu::k_obstacle_metaballs);
  }
  return int32_t(gpu::k_obstacle_sphere);
}

}  // namespace

std::vector<int32_t> scene_specialization(const SimulationSetup& setup) {
  const Scene& scene = setup.scene;
  if (scene.obstacles.size() > size_t(gpu::k_max_obstacles))
    throw std::invalid_argument("liquid: " + std::to_string(scene.obstacles.size()) + " obstacles (at most " +
                                std::to_string(gpu::k_max_obstacles) + ")");
  std::vector<int32_t> constants(specialization_id::count, 0);
  constants[specialization_id::obstacle_count] = int32_t(scene.obstacles.size());
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    constants[specialization_id::first_obstacle_kind + i] = obstacle_kind(scene.obstacles[i].shape);
  constants[specialization_id::shallow_water] = scene.mode == SimulationMode::ShallowWater ? 1 : 0;
  const bool integer_gamma = setup.gamma >= 1.0f && setup.gamma <= 8.0f && setup.gamma == std::floor(setup.gamma);
  constants[specialization_id::integer_gamma] = integer_gamma ? int32_t(setup.gamma) : 0;
  constants[specialization_id::has_emitters] = scene.emitters.empty() ? 0 : 1;
  if (scene.ground.size() > size_t(gpu::k_max_ground))
    throw std::invalid_argument("liquid: " + std::to_string(scene.ground.size()) + " ground hills (at most " +
                                std::to_string(gpu::k_max_ground) + ")");
  constants[specialization_id::ground_hills] = int32_t(scene.ground.size());
  return constants;
}

}  // namespace liquid
