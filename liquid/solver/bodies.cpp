#include "liquid/solver/bodies.h"

#include "liquid/physics/body.h"
#include "liquid/solver/gpu_types.h"

#include <algorithm>

namespace liquid {

int gpu_body_texels() { return gpu::k_body_texels; }

std::vector<glm::vec4> initial_body_texels(const Scene& scene, const SimulationSetup& setup) {
  const size_t rows = std::max<size_t>(1, scene.obstacles.size());
  std::vector<glm::vec4> texels(rows * gpu::k_body_texels, glm::vec4(0.0f));
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    if (!o.dynamic) continue;
    glm::vec4* row = &texels[i * gpu::k_body_texels];
    row[LIQUID_BODY_POSITION] = glm::vec4(o.center, 1.0f);
    row[LIQUID_BODY_ORIENTATION] = glm::vec4(o.rotation.x, o.rotation.y, o.rotation.z, o.rotation.w);
    row[LIQUID_BODY_VELOCITY] = glm::vec4(o.velocity, 0.0f);
    row[LIQUID_BODY_ANGULAR_VELOCITY] = glm::vec4(o.angular_velocity, 0.0f);
    row[LIQUID_BODY_ACCELERATION] = glm::vec4(setup.gravity, 0.0f);
  }
  return texels;
}

std::vector<BodyState> decode_bodies(const Scene& scene, int dimension, const std::vector<glm::vec4>& texels) {
  std::vector<BodyState> bodies;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (!scene.obstacles[i].dynamic) continue;
    const size_t row = i * gpu::k_body_texels;
    if (row + gpu::k_body_texels > texels.size()) break;
    const auto at = [&](int texel) { return texels[row + size_t(texel)]; };
    BodyState b;
    b.obstacle = int(i);
    b.pose.center = glm::vec3(at(LIQUID_BODY_POSITION));
    const glm::vec4 q = at(LIQUID_BODY_ORIENTATION);
    b.pose.orientation = glm::quat(q.w, q.x, q.y, q.z);
    b.pose.velocity = glm::vec3(at(LIQUID_BODY_VELOCITY));
    b.pose.angular_velocity = glm::vec3(at(LIQUID_BODY_ANGULAR_VELOCITY));
    b.force = glm::vec3(at(LIQUID_BODY_FORCE));
    b.torque = glm::vec3(at(LIQUID_BODY_TORQUE));
    b.mass = float(body_mass(scene.obstacles[i], dimension));
    bodies.push_back(b);
  }
  return bodies;
}

}  // namespace liquid
