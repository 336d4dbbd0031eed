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

// How window pixels map to the scene: the 2D view's fitted layout, or the camera's matrix for the
// 3D view and for shallow water's height field (a 2D simulation drawn in perspective: domain
// (x, y) is the world point (x, height, y) on the ground plane, up = world y).
struct ViewMapping {
  int dimension = 2;
  bool height_field = false;     // 2D shallow water, seen through the camera
  glm::vec2 size{1.0f};          // framebuffer pixels
  glm::vec2 origin{0.0f};        // flat 2D: pixel of the domain's bottom-left corner
  float pixels_per_metre = 1.0f; // flat 2D
  glm::mat4 inverse_view_projection{1.0f};  // 3D and height field
  glm::vec3 domain{1.0f};
  float water_level = 0.0f;      // height field: world y of the water at rest

  // Whether the view is a camera's (3D or height field): rays, orbiting.
  bool perspective() const { return dimension == 3 || height_field; }
  // Flat 2D: the domain point under the pixel (z = 0).
  glm::vec3 to_domain(glm::vec2 pixel) const;
  // Perspective: the view ray through the pixel in world space (origin on the near plane, unit
  // direction).
  void ray(glm::vec2 pixel, glm::vec3& origin, glm::vec3& direction) const;
  // Between the domain's coordinates and the view's world (the same but for the height field;
  // there a domain point is placed at the water's rest level).
  glm::vec3 world_to_domain(glm::vec3 world) const;
  glm::vec3 domain_to_world(glm::vec3 point) const;
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

  // Left press in a perspective view: where the ray (world space) meets the liquid (set by the
  // viewer from the density), or nothing when it misses (3D: the plane through the domain centre
  // is used; height field: the water's rest level).
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
  // The drag plane, in world space: 3D, through `anchor_` facing the camera; height field, the
  // horizontal plane through `anchor_`.
  glm::vec3 anchor_{0.0f};
  std::optional<glm::vec3> last_brush_;
  glm::vec3 smoothed_velocity_{0.0f};
  std::optional<size_t> picked_;
  glm::vec3 pick_offset_{0.0f};
  bool released_pending_ = false;
  size_t released_index_ = 0;
};

}  // namespace viewer
