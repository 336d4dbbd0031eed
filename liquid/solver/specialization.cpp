#include "liquid/solver/specialization.h"

#include "liquid/solver/gpu_types.h"
#include "liquid/solver/uniforms.h"

#include <algorithm>
#include <cmath>

namespace liquid {

std::vector<int32_t> scene_specialization(const Scene& scene, const SimulationSetup& setup) {
  // The lists' sizes were checked when the scene entered the library (liquid/scene/limits.h).
  std::vector<int32_t> constants(specialization_id::count, 0);
  constants[specialization_id::obstacle_count] = int32_t(scene.obstacles.size());
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    constants[specialization_id::first_obstacle_kind + i] = obstacle_code(scene.obstacles[i]);
  constants[specialization_id::shallow_water] = setup.shallow_water ? 1 : 0;
  const bool integer_gamma = setup.gamma >= 1.0f && setup.gamma <= 8.0f && setup.gamma == std::floor(setup.gamma);
  constants[specialization_id::integer_gamma] = integer_gamma ? int32_t(setup.gamma) : 0;
  constants[specialization_id::has_emitters] = scene.emitters.empty() ? 0 : 1;
  constants[specialization_id::ground_hills] = int32_t(scene.ground.size());
  const bool walls_continued = std::all_of(setup.wall_share_beyond.begin(), setup.wall_share_beyond.end(),
                                           [](float share) { return share == 0.0f; });
  constants[specialization_id::walls_continued] = walls_continued ? 1 : 0;
  return constants;
}

}  // namespace liquid
