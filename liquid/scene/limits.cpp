#include "liquid/scene/limits.h"

#include "shaders/liquid/shared.h"

#include <string>

namespace liquid {
namespace {

void require_at_most(const Scene& scene, const char* list, size_t count, int limit, const char* what = "") {
  if (count > size_t(limit))
    throw SceneError((scene.source.empty() ? scene.name : scene.source) + ": " + list + ": at most " +
                     std::to_string(limit) + what + " are supported, got " + std::to_string(count));
}

}  // namespace

void check_list_limits(const Scene& scene) {
  require_at_most(scene, "fluid_blocks", scene.fluid_blocks.size(), k_max_fluid_blocks);
  require_at_most(scene, "emitters", scene.emitters.size(), gpu::k_max_emitters);
  require_at_most(scene, "obstacles", scene.obstacles.size(), gpu::k_max_obstacles);
  size_t balls = 0;
  for (const Obstacle& o : scene.obstacles) balls += o.balls.size();
  require_at_most(scene, "obstacles", balls, gpu::k_max_balls, " metaballs in all");
  require_at_most(scene, "ground", scene.ground.size(), gpu::k_max_ground_hills);
}

}  // namespace liquid
