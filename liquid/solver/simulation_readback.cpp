// Simulation's blocking read-backs of its state (particles, grids, bodies) and the per-frame
// read-back of the bodies' state that completes frames_in_flight frames later (latest_bodies()).
#include "engine/graph/transfer.h"
#include "liquid/solver/bodies.h"
#include "liquid/solver/simulation.h"
#include "liquid/solver/texels.h"

#include <glm/gtc/packing.hpp>

#include <cstdint>

namespace liquid {

std::vector<BodyState> Simulation::read_bodies() {
  if (!body_integration_) return {};
  const auto bytes = engine::graph::download_image(context_, state_->bodies[state_->body_current]);
  const engine::vk::ImageDesc& d = state_->bodies[state_->body_current].desc();
  bodies_ = decode_bodies(scene_, setup_.dimension, texels_as<glm::vec4>(bytes, size_t(d.width) * d.height));
  return bodies_;
}

void Simulation::collect_body_readbacks() {
  // A frame is complete once frames_in_flight later ones have been declared (LiquidOptions).
  const BodyReadback* newest = nullptr;
  for (const BodyReadback& r : body_readbacks_)
    if (r.readback.buffer && r.frame + frames_in_flight_ <= frames_declared_ && (!newest || r.frame > newest->frame))
      newest = &r;
  if (!newest) return;
  const engine::vk::ImageDesc& d = newest->readback.desc;
  const auto bytes = newest->readback.bytes();
  bodies_ = decode_bodies(scene_, setup_.dimension,
                          texels_as<glm::vec4>(std::vector<std::byte>(bytes.begin(), bytes.end()), size_t(d.width) * d.height));
  for (BodyReadback& r : body_readbacks_)
    if (r.frame <= newest->frame) r.readback = {};
}

std::vector<BodyState> Simulation::latest_bodies() {
  collect_body_readbacks();
  return bodies_;
}

ParticleSnapshot Simulation::read_particles() {
  ParticleSnapshot snapshot;
  snapshot.positions =
      texels_as<glm::vec4>(engine::graph::download_image(context_, state_->positions[state_->current]), size_t(active_));
  snapshot.velocities =
      texels_as<glm::vec4>(engine::graph::download_image(context_, state_->velocities[state_->current]), size_t(active_));
  return snapshot;
}

std::vector<float> Simulation::read_density_ratio() {
  const auto bytes = engine::graph::download_image(context_, state_->density);
  std::vector<float> ratio(bytes.size() / 2);
  const uint16_t* halves = reinterpret_cast<const uint16_t*>(bytes.data());
  for (size_t i = 0; i < ratio.size(); ++i) ratio[i] = glm::unpackHalf1x16(halves[i]);
  return variant_.layout.to_linear(ratio);
}

std::vector<glm::vec4> Simulation::read_splat() {
  const engine::vk::ImageDesc& d = state_->splat.desc();
  const size_t texels = size_t(d.width) * d.height * d.depth_or_layers;
  const auto bytes = engine::graph::download_image(context_, state_->splat);
  if (d.format == VK_FORMAT_R32G32B32A32_SFLOAT) return variant_.layout.to_linear(texels_as<glm::vec4>(bytes, texels));
  std::vector<glm::vec4> out(texels);
  const uint16_t* halves = reinterpret_cast<const uint16_t*>(bytes.data());
  for (size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 4; ++c) out[i][c] = glm::unpackHalf1x16(halves[i * 4 + c]);
  return variant_.layout.to_linear(out);
}

std::vector<glm::vec4> Simulation::read_grid_velocity() {
  const engine::vk::ImageDesc& d = state_->grid_velocity.desc();
  const size_t texels = size_t(d.width) * d.height * d.depth_or_layers;
  return variant_.layout.to_linear(texels_as<glm::vec4>(engine::graph::download_image(context_, state_->grid_velocity), texels));
}

}  // namespace liquid
