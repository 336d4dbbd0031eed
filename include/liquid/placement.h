// Where the liquid's frame (metres, the domain [0, domain], y up) lies in a host's world: a
// rotation, a translation and a uniform scale (a tank of water somewhere in the level). The solver
// works in the liquid's frame; a node maps what a host gives or reads in world coordinates
// (liquid::Frame::World) through its placement, and a compositing renderer draws with it.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace liquid {

// Which frame a position, velocity or force brush is given or reported in.
enum class Frame {
  Liquid,  // the liquid's own: metres, the domain [0, domain], y up (the default everywhere)
  World,   // the host's: through the node's Placement
};

struct Placement {
  glm::vec3 translation{0.0f};             // world position of the liquid's origin (the domain's corner)
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit
  float scale = 1.0f;                      // world units per metre of the liquid, > 0

  // world = translation + scale * rotation * liquid
  glm::mat4 world_from_liquid() const;
  glm::vec3 point_to_world(glm::vec3 p) const { return translation + scale * (rotation * p); }
  glm::vec3 point_to_liquid(glm::vec3 p) const { return glm::inverse(rotation) * (p - translation) / scale; }
  // Velocities, accelerations and other free vectors: rotated and scaled, not moved.
  glm::vec3 vector_to_world(glm::vec3 v) const { return scale * (rotation * v); }
  glm::vec3 vector_to_liquid(glm::vec3 v) const { return glm::inverse(rotation) * v / scale; }
};

}  // namespace liquid
