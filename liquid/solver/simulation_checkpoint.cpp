// Simulation's checkpoints: the particle and body textures downloaded with the clock and the host's
// inputs, each value checked before a checkpoint is restored.
#include "engine/graph/transfer.h"
#include "liquid/scene/format.h"
#include "liquid/solver/bodies.h"
#include "liquid/solver/simulation.h"
#include "liquid/solver/texels.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace liquid {

engine::vk::Image* Simulation::projection_pressure() const {
  return pressure_ ? pressure_->projection_pressure() : nullptr;
}

size_t Simulation::projection_values() const {
  const engine::vk::Image* p = projection_pressure();
  return p ? size_t(p->desc().width) * p->desc().height * p->desc().depth_or_layers * k_projection_pressure_channels : 0;
}

Checkpoint Simulation::save_checkpoint() {
  Checkpoint c;
  c.step = step_;
  c.time = time_;
  c.time_step = time_step_;
  c.active = active_;
  host_.save(c);
  const size_t texels = size_t(setup_.particle_texture.x) * setup_.particle_texture.y;
  c.positions = texels_as<glm::vec4>(engine::graph::download_image(context_, state_->positions[state_->current]), texels);
  c.velocities =
      texels_as<glm::vec4>(engine::graph::download_image(context_, state_->velocities[state_->current]), texels);
  for (engine::vk::Image& image : state_->affine[state_->current]) {
    const auto affine = texels_as<glm::vec4>(engine::graph::download_image(context_, image), texels);
    c.affine.insert(c.affine.end(), affine.begin(), affine.end());
  }
  engine::vk::Image& bodies = state_->bodies[state_->body_current];
  c.bodies = texels_as<glm::vec4>(engine::graph::download_image(context_, bodies),
                                  size_t(bodies.desc().width) * bodies.desc().height);
  if (whitewater_) c.whitewater = whitewater_->save();
  if (engine::vk::Image* p = projection_pressure())
    c.pressure = texels_as<float>(engine::graph::download_image(context_, *p), projection_values());
  return c;
}

// Every value a checkpoint carries within what a run can reach, so a damaged or edited one is
// refused naming the value rather than run (a NaN position used to surface as "simulation
// unstable" steps later).
void Simulation::check_checkpoint_values(const Checkpoint& c) const {
  const auto refuse = [](const std::string& what) { throw ArgumentError("liquid: the checkpoint's " + what); };
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (c.step < 0) refuse("step count is negative (" + std::to_string(c.step) + ")");
  if (!(std::isfinite(c.time) && c.time >= 0.0)) refuse("time is not a finite time >= 0 s");
  if (!(std::isfinite(c.time_step) && c.time_step >= 0.0 && c.time_step <= double(setup_.time_step) * (1.0 + 1e-6)))
    refuse("time step is not in [0, " + format_number(setup_.time_step) + "] s");
  for (size_t e = 0; e < c.emitted.size(); ++e)
    if (c.emitted[e] < 0 || c.emitted[e] > scene_.emitters[e].capacity)
      refuse("emitter " + std::to_string(e) + " has added " + std::to_string(c.emitted[e]) + " particles, outside [0, " +
             std::to_string(scene_.emitters[e].capacity) + "]");
  for (size_t i = 0; i < c.poses.size(); ++i)
    if (!finite(c.poses[i].center) || !finite(c.poses[i].velocity) || !std::isfinite(c.poses[i].since))
      refuse("obstacle " + std::to_string(i) + " has a non-finite pose");
  for (size_t i = 0; i < c.bodies.size(); ++i)
    if (!finite(glm::vec3(c.bodies[i])) || !std::isfinite(c.bodies[i].w))
      refuse("body state holds a non-finite value (texel " + std::to_string(i) + ")");
  for (size_t i = 0; i < c.pressure.size(); ++i)
    if (!std::isfinite(c.pressure[i]))
      refuse("pressure holds a non-finite value (texel " + std::to_string(i / k_projection_pressure_channels) + ")");
  // The active particles' C_p (the texels past them are never read).
  const size_t texels = c.positions.size();
  for (size_t i = 0; i < c.affine.size(); ++i)
    if (int(i % texels) < c.active && (!finite(glm::vec3(c.affine[i])) || !std::isfinite(c.affine[i].w)))
      refuse("velocity gradients hold a non-finite value (particle " + std::to_string(i % texels) + ")");
  for (int i = 0; i < c.active; ++i) {
    const glm::vec4 p = c.positions[size_t(i)], v = c.velocities[size_t(i)];
    if (!finite(glm::vec3(p)) || !finite(glm::vec3(v)))
      refuse("particle " + std::to_string(i) + " has a non-finite position or velocity");
    for (int a = 0; a < setup_.dimension; ++a)
      if (p[a] < 0.0f || p[a] > setup_.domain[a])
        refuse("particle " + std::to_string(i) + " lies outside the domain (" + format_number(p[a]) + " m on axis " +
               std::to_string(a) + ")");
  }
}

void Simulation::restore_checkpoint(const Checkpoint& c) {
  const size_t texels = size_t(setup_.particle_texture.x) * setup_.particle_texture.y;
  if (c.active < 0 || c.active > setup_.capacity)
    throw ArgumentError("liquid: the checkpoint holds " + std::to_string(c.active) +
                        " active particles, outside the scene's capacity of 0 to " + std::to_string(setup_.capacity));
  const engine::vk::ImageDesc& body_desc = state_->bodies[0].desc();
  if (c.positions.size() != texels || c.velocities.size() != texels || c.emitted.size() != scene_.emitters.size() ||
      c.poses.size() != scene_.obstacles.size() || c.bodies.size() != size_t(body_desc.width) * body_desc.height ||
      c.affine.size() != texels * state_->affine[0].size() || c.pressure.size() != projection_values())
    throw ArgumentError("liquid: the checkpoint does not match this scene (" + std::to_string(c.positions.size()) +
                        " particle texels, " + std::to_string(c.emitted.size()) + " emitters, " +
                        std::to_string(c.poses.size()) + " obstacles; the scene has " + std::to_string(texels) +
                        ", " + std::to_string(scene_.emitters.size()) + ", " +
                        std::to_string(scene_.obstacles.size()) + ")");
  check_checkpoint_values(c);
  if (bool(whitewater_) != !c.whitewater.empty())
    throw ArgumentError(std::string("liquid: the checkpoint ") + (whitewater_ ? "has no" : "has") +
                        " whitewater; the scene " + (whitewater_ ? "has" : "has none"));
  if (whitewater_) whitewater_->restore(c.whitewater);
  engine::graph::upload_image(context_, state_->positions[state_->current], std::as_bytes(std::span(c.positions)));
  engine::graph::upload_image(context_, state_->velocities[state_->current], std::as_bytes(std::span(c.velocities)));
  for (size_t a = 0; a < state_->affine[state_->current].size(); ++a)
    engine::graph::upload_image(context_, state_->affine[state_->current][a],
                                std::as_bytes(std::span(c.affine).subspan(a * texels, texels)));
  engine::graph::upload_image(context_, state_->bodies[state_->body_current], std::as_bytes(std::span(c.bodies)));
  if (engine::vk::Image* p = projection_pressure())
    engine::graph::upload_image(context_, *p, std::as_bytes(std::span(c.pressure)));
  bodies_ = decode_bodies(scene_, setup_.dimension, c.bodies);
  for (BodyReadback& r : body_readbacks_) r.readback = {};
  step_ = c.step;
  time_ = c.time;
  time_step_ = c.time_step > 0.0 ? c.time_step : double(setup_.time_step);
  active_ = c.active;
  host_.restore(c);
}

}  // namespace liquid
