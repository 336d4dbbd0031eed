#include "liquid/analysis/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace liquid {

Diagnostics compute_diagnostics(const Scene& scene, const SimulationSetup& setup, const ParticleSnapshot& particles,
                                const std::vector<float>& density_ratio,
                                const std::vector<ObstaclePose>& obstacle_poses, int step, double time) {
  Diagnostics d;
  std::vector<PlacedObstacle> obstacles;  // the sign is all the count needs: a mesh's reach is one cell
  for (size_t o = 0; o < scene.obstacles.size(); ++o)
    obstacles.emplace_back(scene.obstacles[o], o < obstacle_poses.size() ? obstacle_poses[o] : scripted_pose(scene.obstacles[o], 0.0),
                           setup.dimension, setup.cell_size);
  d.step = step;
  d.time = time;
  d.time_step = setup.time_step;  // the node replaces it with the last step's when steps adapt
  d.active_particles = int(particles.positions.size());
  const double m = setup.particle_mass;
  // Potential energy relative to the domain's lowest corner along gravity (the floor for g = -y).
  const glm::dvec3 g(setup.gravity);
  double lowest = 0.0;
  for (int corner = 0; corner < (1 << setup.dimension); ++corner) {
    glm::dvec3 p(0.0);
    for (int a = 0; a < setup.dimension; ++a) p[a] = (corner >> a) & 1 ? double(setup.domain[a]) : 0.0;
    lowest = std::min(lowest, -glm::dot(g, p));
  }
  glm::dvec3 weighted(0.0);
  for (size_t i = 0; i < particles.positions.size(); ++i) {
    const glm::vec3 x = particles.positions[i];
    const glm::vec3 v = particles.velocities[i];
    const bool finite = std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) && std::isfinite(v.x) &&
                        std::isfinite(v.y) && std::isfinite(v.z);
    if (!finite) {
      ++d.non_finite;
      continue;
    }
    for (int a = 0; a < setup.dimension; ++a)
      if (x[a] < 0.0f || x[a] > setup.domain[a]) {
        ++d.outside_domain;
        break;
      }
    for (const PlacedObstacle& o : obstacles) {
      if (o.distance(x) < 0.0f) {
        ++d.inside_obstacles;
        break;
      }
    }
    const double speed2 = glm::dot(glm::dvec3(v), glm::dvec3(v));
    d.kinetic_energy += 0.5 * m * speed2;
    d.potential_energy += m * (-glm::dot(g, glm::dvec3(x)) - lowest);
    d.max_speed = std::max(d.max_speed, float(std::sqrt(speed2)));
    weighted += glm::dvec3(x);
  }
  d.mass = m * d.active_particles;
  d.mechanical_energy = d.kinetic_energy + d.potential_energy;
  const int finite_count = d.active_particles - d.non_finite;
  if (finite_count > 0) d.center_of_mass = glm::vec3(weighted / double(finite_count));
  for (float r : density_ratio)
    if (std::isfinite(r)) d.max_density_ratio = std::max(d.max_density_ratio, r);
  return d;
}

double kinetic_energy_bound(const Scene& scene, const SimulationSetup& setup, double factor) {
  double speed2 = 2.0 * glm::length(setup.gravity) * setup.domain.y;  // a fall over the domain height
  for (const FluidBlock& b : scene.fluid_blocks) speed2 = std::max(speed2, double(glm::dot(b.velocity, b.velocity)));
  for (const Emitter& e : scene.emitters) speed2 = std::max(speed2, double(glm::dot(e.velocity, e.velocity)));
  for (const Obstacle& o : scene.obstacles) {
    const double s = glm::length(o.velocity) + 2.0 * M_PI * o.oscillation_frequency * glm::length(o.oscillation_amplitude);
    speed2 = std::max(speed2, s * s);
  }
  speed2 = std::max(speed2, 1.0);  // at least 1 m/s of motion is never "unstable"
  return factor * 0.5 * setup.particle_mass * setup.capacity * speed2;
}

void check_stable(const Diagnostics& d, double energy_bound) {
  if (d.non_finite > 0) {
    std::ostringstream message;
    message << "simulation unstable at step " << d.step << " (t = " << d.time << " s): " << d.non_finite
            << " particle(s) with NaN or Inf";
    throw SimulationError(message.str());
  }
  for (const BodyState& b : d.bodies) {
    const glm::vec3 v[] = {b.pose.center, b.pose.velocity, b.pose.angular_velocity, b.force, b.torque};
    for (const glm::vec3& x : v)
      if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) {
        std::ostringstream message;
        message << "simulation unstable at step " << d.step << " (t = " << d.time << " s): obstacle " << b.obstacle
                << " (a dynamic body) has a NaN or Inf state";
        throw SimulationError(message.str());
      }
  }
  if (d.kinetic_energy > energy_bound) {
    std::ostringstream message;
    message << "simulation unstable at step " << d.step << " (t = " << d.time << " s): kinetic energy "
            << d.kinetic_energy << " J exceeds the bound " << energy_bound
            << " J (reduce time_step or stiffness)";
    throw SimulationError(message.str());
  }
}

}  // namespace liquid
