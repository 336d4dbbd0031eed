#include "liquid/physics/obstacles.h"

#include <algorithm>
#include <cmath>

namespace liquid {

ObstaclePose scripted_pose(const Obstacle& obstacle, double time) {
  const double omega = 2.0 * M_PI * obstacle.oscillation_frequency;
  const glm::vec3 wave = obstacle.oscillation_amplitude * float(std::sin(omega * time));
  const glm::vec3 wave_velocity = obstacle.oscillation_amplitude * float(omega * std::cos(omega * time));
  if (obstacle.dynamic) return {obstacle.center, obstacle.velocity, obstacle.rotation, obstacle.angular_velocity};
  return {obstacle.center + obstacle.velocity * float(time) + wave, obstacle.velocity + wave_velocity,
          spun_rotation(obstacle, time), obstacle.angular_velocity};
}

glm::quat spun_rotation(const Obstacle& obstacle, double time) {
  const glm::vec3 w = obstacle.angular_velocity;
  const double speed = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
  if (speed == 0.0) return obstacle.rotation;
  // The angle modulo a turn, in double: a float angle loses the spin's phase after a few minutes.
  const double angle = std::fmod(speed * time, 2.0 * M_PI);
  return glm::normalize(glm::angleAxis(float(angle), w / float(speed)) * obstacle.rotation);
}

glm::vec3 turn_rate(glm::quat from, glm::quat to, double seconds) {
  if (!(seconds > 0.0)) return glm::vec3(0.0f);
  glm::quat delta = glm::normalize(to * glm::inverse(from));
  if (delta.w < 0.0f) delta = -delta;  // the shorter way round
  const glm::vec3 axis(delta.x, delta.y, delta.z);
  const float s = glm::length(axis);
  if (s == 0.0f) return glm::vec3(0.0f);
  const double angle = 2.0 * std::atan2(double(s), double(delta.w));
  return axis / s * float(angle / seconds);
}

glm::vec3 obstacle_velocity_at(const ObstaclePose& pose, glm::vec3 p) {
  return pose.velocity + glm::cross(pose.angular_velocity, p - pose.center);
}

float obstacle_distance(const Obstacle& obstacle, const ObstaclePose& pose, glm::vec3 p, int dimension) {
  glm::vec3 local = glm::inverse(pose.orientation) * (p - pose.center);
  if (dimension == 2) local.z = 0.0f;
  switch (obstacle.shape) {
    case ObstacleShape::Sphere:
      return glm::length(local) - obstacle.radius;
    case ObstacleShape::Box: {
      // In 2D the rectangle's distance: a z extent of 1 m keeps z out of it, as in common.glsl.
      const glm::vec3 half = dimension == 2 ? glm::vec3(glm::vec2(obstacle.half_extent), 1.0f) : obstacle.half_extent;
      const glm::vec3 q = glm::abs(local) - half;
      return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    }
    case ObstacleShape::Metaballs: {
      float field = 0.0f, reach = 0.0f;
      glm::vec3 gradient(0.0f);
      for (const Metaball& ball : obstacle.balls) {
        const glm::vec3 d = local - ball.center;
        const float q = glm::dot(d, d) / (ball.radius * ball.radius);
        reach = std::max(reach, glm::length(ball.center) + ball.radius);
        if (q < 1.0f) {
          field += (1.0f - q) * (1.0f - q);
          gradient += -4.0f * (1.0f - q) * d / (ball.radius * ball.radius);
        }
      }
      if (field <= 0.0f) return std::max(glm::length(local) - reach, 1e-3f) + 1e-3f;
      return (obstacle.threshold - field) / std::max(glm::length(gradient), 1e-4f);
    }
    case ObstacleShape::Mesh:  // one query: PlacedObstacle serves many
      return PlacedMesh(obstacle.mesh, pose.center, pose.orientation, 1e30f)
          .distance(dimension == 2 ? glm::vec3(p.x, p.y, 0.0f) : p);
  }
  return 1e30f;
}

PlacedObstacle::PlacedObstacle(const Obstacle& obstacle, const ObstaclePose& pose, int dimension, float mesh_reach)
    : obstacle_(&obstacle), pose_(pose), dimension_(dimension) {
  if (obstacle.shape == ObstacleShape::Mesh) mesh_.emplace(obstacle.mesh, pose.center, pose.orientation, mesh_reach);
}

float PlacedObstacle::distance(glm::vec3 p) const {
  if (!mesh_) return obstacle_distance(*obstacle_, pose_, p, dimension_);
  if (dimension_ == 2) p.z = 0.0f;
  return mesh_->distance(p);
}

}  // namespace liquid
