// A pinhole camera in scene units (metres), and the matrices the render passes use.
#pragma once

#include <glm/glm.hpp>

namespace liquid {

class LiquidNode;

struct CameraView {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
};

// The scene's camera, or one that frames the whole domain from the front, slightly above; for
// shallow water, the height-field view's camera (default_height_field_camera).
CameraView default_camera(const LiquidNode& node);

// Vulkan clip space (y down, depth 0..1): projection * view.
glm::mat4 view_projection(const CameraView& camera, float aspect, float near_plane, float far_plane);

}  // namespace liquid
