#include "liquid/camera.h"

#include "liquid/node.h"
#include "liquid/physics/setup.h"
#include "liquid/render/height_field.h"
#include "liquid/solver/node_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace liquid {

CameraView default_camera(const LiquidNode& node) {
  const Scene& scene = node.scene();
  const SimulationSetup& setup = node_setup(node);
  if (setup.shallow_water) return default_height_field_camera(scene, setup);
  if (scene.camera) {
    const Camera& c = *scene.camera;
    return {c.position, c.target, {0.0f, 1.0f, 0.0f}, c.fov_y_degrees};
  }
  const glm::vec3 d = setup.domain;
  const glm::vec3 center = d * 0.5f;
  const float extent = std::max({d.x, d.y, d.z});
  return {center + glm::vec3(0.25f * d.x, 0.55f * extent, 1.6f * extent + 0.5f * d.z), center * glm::vec3(1, 0.6f, 1),
          {0.0f, 1.0f, 0.0f}, 40.0f};
}

glm::mat4 view_projection(const CameraView& camera, float aspect, float near_plane, float far_plane) {
  glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(camera.fov_y_degrees), aspect, near_plane, far_plane);
  projection[1][1] *= -1.0f;  // Vulkan's y points down
  return projection * glm::lookAtRH(camera.position, camera.target, camera.up);
}

}  // namespace liquid
