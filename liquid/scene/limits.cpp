#include "liquid/scene/limits.h"

#include "liquid/scene/mesh_check.h"
#include "shaders/liquid/shared.h"

#include <cmath>
#include <string>

namespace liquid {
namespace {

// What an error names first: the file, or a scene built in code by its name.
std::string label(const Scene& scene) { return scene.source.empty() ? scene.name : scene.source; }

void require_at_most(const Scene& scene, const char* list, size_t count, int limit, const char* what = "") {
  if (count > size_t(limit))
    throw SceneError(label(scene) + ": " + list + ": at most " +
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
  size_t meshes = 0;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (scene.obstacles[i].shape != ObstacleShape::Mesh) continue;
    ++meshes;
    // A file's mesh was checked when read; a host's (built in code) is checked here.
    const TriangleMesh& mesh = scene.obstacles[i].mesh;
    if (const std::string problem = mesh_problem(mesh); !problem.empty())
      throw SceneError(label(scene) + ": obstacles[" + std::to_string(i) +
                       "]: " + (mesh.file.empty() ? "the host's mesh" : mesh.file) + ": " + problem);
    if (!(mesh.scale > 0.0f && std::isfinite(mesh.scale)))
      throw SceneError(label(scene) + ": obstacles[" + std::to_string(i) +
                       "]: the mesh's scale must be a finite number > 0");
    // The scene file refuses it too (liquid/scene/scene.cpp); a host's scene is checked here.
    if (scene.obstacles[i].dynamic && scene.dimension != 3)
      throw SceneError(label(scene) + ": obstacles[" + std::to_string(i) +
                       "].dynamic: a mesh obstacle can be dynamic in 3D only");
  }
  require_at_most(scene, "obstacles", meshes, gpu::k_max_mesh_obstacles, " meshes");
}

void check_projection(const Scene& scene) {
  const std::string prefix = label(scene) + ": projection_iterations: ";
  // The first iteration reads the last step's solution and the last writes the next's: two at least.
  const int iterations = projection_iterations_of(scene);  // shallow water runs none
  if (iterations == 1) throw SceneError(prefix + "must be 0 (no projection) or at least 2, got 1");
  if (iterations > 0 && scene.pressure_force != PressureForce::SplatAdjoint)
    throw SceneError(prefix + "needs \"pressure_force\": \"splat_adjoint\" (set it to 0 for the chapter's pressure), got " +
                     std::to_string(iterations));
}

}  // namespace liquid
