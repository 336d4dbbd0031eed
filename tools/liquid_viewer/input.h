// Input as the viewer sees it, whether it comes from the window or from a replayed script, and
// what the mouse does to the liquid: the force brush (left drag), the nearest obstacle (right
// drag) and the 3D camera (middle drag orbits, shift + middle drag pans, ctrl + wheel zooms).
#pragma once

#include "liquid/camera.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace viewer {

enum class MouseButton { Left, Right, Middle };

struct InputEvent {
  enum class Type { Move, Press, Release, Scroll, Key, Resize };
  Type type = Type::Move;
  float x = 0.0f, y = 0.0f;  // cursor, window pixels (y down)
  MouseButton button = MouseButton::Left;
  float scroll = 0.0f;       // wheel clicks, up > 0
  int key = 0;               // GLFW key code
  int mods = 0;              // GLFW modifier bits
  uint32_t width = 0, height = 0;  // Resize
};

// How window pixels map to the scene: the 2D view's fitted layout, or the 3D camera's matrix.
struct ViewMapping {
  int dimension = 2;
  glm::vec2 size{1.0f};          // framebuffer pixels
  glm::vec2 origin{0.0f};        // 2D: pixel of the domain's bottom-left corner
  float pixels_per_metre = 1.0f; // 2D
  glm::mat4 inverse_view_projection{1.0f};  // 3D
  glm::vec3 domain{1.0f};

  // 2D: the domain point under the pixel (z = 0).
  glm::vec3 to_domain(glm::vec2 pixel) const;
  // 3D: the view ray through the pixel (origin on the near plane, unit direction).
  void ray(glm::vec2 pixel, glm::vec3& origin, glm::vec3& direction) const;
};

// An orbiting camera around a target (the 3D view's).
struct OrbitCamera {
  glm::vec3 target{0.0f};
  float yaw = 0.0f, pitch = 0.0f, distance = 1.0f;  // radians, metres
  float fov_y_degrees = 45.0f;
  static OrbitCamera from(const liquid::CameraView& view);
  liquid::CameraView view() const;
};

// What the mouse does this frame, handed to the node by the viewer.
struct Interaction {
  std::vector<liquid::ForceBrush> brushes;
  struct ObstacleMove {
    size_t index = 0;
    glm::vec3 target{0.0f};  // where the cursor wants the obstacle's centre at the end of the frame
  };
  std::optional<ObstacleMove> obstacle;
  std::optional<size_t> released_obstacle;  // stop it where it is
};

class MouseTools {
 public:
  float brush_radius = 0.08f;    // m
  float brush_strength = 20.0f;  // 1/s: acceleration per drag speed
  float max_acceleration = 300.0f;  // m/s^2

  // Left press in 3D: where the ray meets the liquid (set by the viewer from the density), or
  // nothing when it misses (the plane through the domain centre is used).
  std::function<std::optional<glm::vec3>(glm::vec3 origin, glm::vec3 direction)> surface_hit;
  // Obstacle centres now, for picking with the right button.
  std::function<std::vector<glm::vec3>()> obstacle_centers;

  // Feeds one event; returns true when it was a mouse event the tools used.
  bool handle(const InputEvent& event, const ViewMapping& mapping, OrbitCamera& camera);
  // This frame's brushes and obstacle move; `frame_seconds` is the simulated time of the frame.
  Interaction frame(const ViewMapping& mapping, float frame_seconds);
  bool dragging() const { return left_ || right_; }
  glm::vec2 cursor() const { return cursor_; }

 private:
  glm::vec3 point_on_drag_plane(const ViewMapping& mapping, glm::vec2 pixel) const;

  glm::vec2 cursor_{0.0f};
  bool left_ = false, right_ = false, middle_ = false;
  int middle_mods_ = 0;
  glm::vec2 middle_last_{0.0f};
  // The drag plane (3D): through `anchor_`, facing the camera.
  glm::vec3 anchor_{0.0f};
  std::optional<glm::vec3> last_brush_;
  glm::vec3 smoothed_velocity_{0.0f};
  std::optional<size_t> picked_;
  glm::vec3 pick_offset_{0.0f};
  bool released_pending_ = false;
  size_t released_index_ = 0;
};

}  // namespace viewer
