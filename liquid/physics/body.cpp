#include "liquid/physics/body.h"

#include <algorithm>
#include <cmath>

namespace liquid {

double body_volume(const Obstacle& o, int dimension) {
  const glm::dvec3 e(o.half_extent);
  const double r = o.radius;
  if (o.shape == ObstacleShape::Box) return dimension == 2 ? 4.0 * e.x * e.y : 8.0 * e.x * e.y * e.z;
  return dimension == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
}

double body_surface(const Obstacle& o, int dimension) {
  const glm::dvec3 e(o.half_extent);
  const double r = o.radius;
  if (o.shape == ObstacleShape::Box) return dimension == 2 ? 4.0 * (e.x + e.y) : 8.0 * (e.x * e.y + e.y * e.z + e.x * e.z);
  return dimension == 2 ? 2.0 * M_PI * r : 4.0 * M_PI * r * r;
}

double body_mass(const Obstacle& o, int dimension) {
  return o.mass > 0.0f ? double(o.mass) : double(o.density) * body_volume(o, dimension);
}

glm::vec3 body_inertia(const Obstacle& o, int dimension) {
  const double m = body_mass(o, dimension);
  const glm::dvec3 e2 = glm::dvec3(o.half_extent) * glm::dvec3(o.half_extent);
  const double r2 = double(o.radius) * o.radius;
  if (dimension == 2) {
    // A rectangle of sides 2a, 2b: m (a^2 + b^2) / 3; a disc: m r^2 / 2.
    const double iz = o.shape == ObstacleShape::Box ? m * (e2.x + e2.y) / 3.0 : 0.5 * m * r2;
    return glm::vec3(float(iz));
  }
  if (o.shape == ObstacleShape::Box) return glm::vec3(glm::dvec3(e2.y + e2.z, e2.x + e2.z, e2.x + e2.y) * (m / 3.0));
  return glm::vec3(float(0.4 * m * r2));
}

double body_added_mass(const Obstacle& o, int dimension, double liquid_density, double cell_size) {
  return liquid_density * (body_volume(o, dimension) + body_surface(o, dimension) * cell_size);
}

double body_added_inertia_ratio(const Obstacle& o, int dimension, double added_mass) {
  const glm::vec3 e = dimension == 2 ? glm::vec3(glm::vec2(o.half_extent), 0.0f) : o.half_extent;
  const double radius = o.shape == ObstacleShape::Box ? double(glm::length(e)) : double(o.radius);
  const glm::vec3 inertia = body_inertia(o, dimension);
  return added_mass * radius * radius / double(std::min(inertia.x, std::min(inertia.y, inertia.z)));
}

}  // namespace liquid
