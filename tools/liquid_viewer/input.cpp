#include "tools/liquid_viewer/input.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viewer {

glm::vec3 ViewMapping::to_domain(glm::vec2 pixel) const {
  return {(pixel.x - origin.x) / pixels_per_metre, (origin.y - pixel.y) / pixels_per_metre, 0.0f};
}

void ViewMapping::ray(glm::vec2 pixel, glm::vec3& ray_origin, glm::vec3& direction) const {
  // Vulkan clip space: x and y in [-1, 1] with y down, depth 0 (near) to 1 (far).
  const glm::vec2 ndc = 2.0f * (pixel + 0.5f) / size - 1.0f;
  const glm::vec4 near_point = inverse_view_projection * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec4 far_point = inverse_view_projection * glm::vec4(ndc, 1.0f, 1.0f);
  ray_origin = glm::vec3(near_point) / near_point.w;
  direction = glm::normalize(glm::vec3(far_point) / far_point.w - ray_origin);
}

glm::vec3 ViewMapping::world_to_domain(glm::vec3 world) const {
  return height_field ? glm::vec3(world.x, world.z, 0.0f) : world;
}

glm::vec3 ViewMapping::domain_to_world(glm::vec3 point) const {
  return height_field ? glm::vec3(point.x, water_level, point.y) : point;
}

OrbitCamera OrbitCamera::from(const liquid::CameraView& view) {
  OrbitCamera c;
  c.target = view.target;
  const glm::vec3 offset = view.position - view.target;
  c.distance = std::max(glm::length(offset), 1e-3f);
  c.yaw = std::atan2(offset.x, offset.z);
  c.pitch = std::asin(std::clamp(offset.y / c.distance, -1.0f, 1.0f));
  c.fov_y_degrees = view.fov_y_degrees;
  return c;
}

liquid::CameraView OrbitCamera::view() const {
  const glm::vec3 offset{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
  return {target + distance * offset, target, {0.0f, 1.0f, 0.0f}, fov_y_degrees};
}

glm::vec3 MouseTools::point_on_drag_plane(const ViewMapping& mapping, glm::vec2 pixel) const {
  if (!mapping.perspective()) return mapping.to_domain(pixel);
  glm::vec3 origin, direction, normal;
  mapping.ray(pixel, origin, direction);
  if (mapping.height_field) {
    normal = {0.0f, 1.0f, 0.0f};  // the brush slides over the water, at the height it touched
  } else {
    glm::vec3 centre_origin;
    mapping.ray(0.5f * mapping.size, centre_origin, normal);  // the view direction
  }
  const float along = glm::dot(normal, direction);
  const float t = std::abs(along) < 1e-6f ? -1.0f : glm::dot(anchor_ - origin, normal) / along;
  // A ray parallel to the plane, or meeting it behind the camera (above the horizon), keeps the anchor.
  if (t < 0.0f) return mapping.world_to_domain(anchor_);
  return mapping.world_to_domain(origin + direction * t);
}

bool MouseTools::handle(const InputEvent& e, const ViewMapping& mapping, OrbitCamera& camera) {
  switch (e.type) {
    case InputEvent::Type::Move: {
      const glm::vec2 p{e.x, e.y};
      if (middle_ && mapping.perspective()) {
        const glm::vec2 d = p - middle_last_;
        if (middle_mods_ & GLFW_MOD_SHIFT) {
          const liquid::CameraView v = camera.view();
          const glm::vec3 forward = glm::normalize(v.target - v.position);
          const glm::vec3 right = glm::normalize(glm::cross(forward, v.up));
          const glm::vec3 up = glm::cross(right, forward);
          camera.target += (-d.x * right + d.y * up) * (camera.distance * 0.0015f);
        } else {
          camera.yaw -= d.x * 0.01f;
          camera.pitch = std::clamp(camera.pitch + d.y * 0.01f, -1.5f, 1.5f);
        }
      }
      middle_last_ = p;
      cursor_ = p;
      return left_ || right_ || middle_;
    }
    case InputEvent::Type::Press:
    case InputEvent::Type::Release: {
      const bool down = e.type == InputEvent::Type::Press;
      cursor_ = {e.x, e.y};
      if (e.button == MouseButton::Middle) {
        middle_ = down;
        middle_mods_ = e.mods;
        middle_last_ = cursor_;
        return true;
      }
      if (e.button == MouseButton::Left) {
        left_ = down;
        last_brush_.reset();
        smoothed_velocity_ = glm::vec3(0.0f);
        if (down && mapping.perspective()) {
          glm::vec3 origin, direction;
          mapping.ray(cursor_, origin, direction);
          const std::optional<glm::vec3> hit = surface_hit ? surface_hit(origin, direction) : std::nullopt;
          anchor_ = hit ? *hit : mapping.domain_to_world(0.5f * mapping.domain);
        }
        return true;
      }
      // Right button: pick the obstacle nearest to the cursor.
      right_ = down;
      if (!down) {
        if (picked_) {
          released_pending_ = true;
          released_index_ = *picked_;
        }
        picked_.reset();
        return true;
      }
      const std::vector<glm::vec3> centers = obstacle_centers ? obstacle_centers() : std::vector<glm::vec3>{};
      float best = std::numeric_limits<float>::max();
      for (size_t i = 0; i < centers.size(); ++i) {
        float distance = 0.0f;
        if (!mapping.perspective()) {
          distance = glm::length(glm::vec2(centers[i]) - glm::vec2(mapping.to_domain(cursor_)));
        } else {
          glm::vec3 origin, direction;
          mapping.ray(cursor_, origin, direction);
          const glm::vec3 to = mapping.domain_to_world(centers[i]) - origin;
          distance = glm::length(to - direction * glm::dot(to, direction));
        }
        if (distance < best) {
          best = distance;
          picked_ = i;
        }
      }
      if (picked_) {
        anchor_ = mapping.domain_to_world(centers[*picked_]);
        pick_offset_ = centers[*picked_] - point_on_drag_plane(mapping, cursor_);
      }
      return true;
    }
    case InputEvent::Type::Scroll:
      if (e.mods & GLFW_MOD_CONTROL) {
        camera.distance = std::clamp(camera.distance * std::pow(0.9f, e.scroll), 0.05f, 100.0f);
      } else {
        brush_radius = std::clamp(brush_radius * std::pow(1.1f, e.scroll), 0.005f, 2.0f);
      }
      return true;
    default: return false;
  }
}

Interaction MouseTools::frame(const ViewMapping& mapping, float frame_seconds) {
  Interaction out;
  if (left_) {
    const glm::vec3 p = point_on_drag_plane(mapping, cursor_);
    if (last_brush_ && frame_seconds > 0.0f)
      smoothed_velocity_ = 0.5f * smoothed_velocity_ + 0.5f * (p - *last_brush_) / frame_seconds;
    last_brush_ = p;
    glm::vec3 acceleration = brush_strength * smoothed_velocity_;
    const float magnitude = glm::length(acceleration);
    if (magnitude > max_acceleration) acceleration *= max_acceleration / magnitude;
    out.brushes.push_back({p, brush_radius, acceleration});
  }
  if (right_ && picked_) {
    glm::vec3 target = point_on_drag_plane(mapping, cursor_) + pick_offset_;
    target = glm::clamp(target, glm::vec3(0.0f), mapping.domain);
    if (mapping.dimension == 2) target.z = 0.0f;
    out.obstacle = Interaction::ObstacleMove{*picked_, target};
  }
  if (released_pending_) {
    out.released_obstacle = released_index_;
    released_pending_ = false;
  }
  return out;
}

}  // namespace viewer
