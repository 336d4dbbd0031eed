#include "liquid/solver/whitewater.h"

#include "engine/graph/transfer.h"
#include "engine/passes/fullscreen.h"
#include "engine/vk/context.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/solver_pass.h"
#include "liquid/solver/state.h"
#include "liquid/solver/texels.h"
#include "liquid_shader_families.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

namespace liquid {

namespace {

// The public kinds are the shader's codes (shared.h), which the public header cannot include.
static_assert(int(WhitewaterKind::Spray) == LIQUID_WHITEWATER_SPRAY && int(WhitewaterKind::Foam) == LIQUID_WHITEWATER_FOAM &&
              int(WhitewaterKind::Bubble) == LIQUID_WHITEWATER_BUBBLE);

std::vector<engine::vk::DescriptorBinding> whitewater_bindings(const SolverVariant& variant) {
  constexpr VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_PARTICLE_POSITIONS, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_PARTICLE_VELOCITIES, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_PARTICLE_GRID_VELOCITY, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_WHITEWATER_POSITIONS, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_WHITEWATER_VELOCITIES, DescriptorKind::SampledImage, fragment},
      {LIQUID_BINDING_WHITEWATER_DENSITY, DescriptorKind::SampledImage, fragment}};
  add_body_shapes_binding(bindings, fragment);
  add_mesh_field_binding(variant.meshes, bindings);
  return bindings;
}

engine::vk::GraphicsPipelineDesc whitewater_pipeline(const SolverVariant& variant, const char* name,
                                                     const ShaderFamily& fragment,
                                                     const std::vector<int32_t>& specialization) {
  return {.name = name,
          .vertex = engine::passes::fullscreen_vertex_shader(),
          .fragment = variant.shader(fragment),
          .color_formats = {k_particle_format, k_particle_format},
          .bindings = whitewater_bindings(variant),
          .push_constant_size = sizeof(gpu::WhitewaterPush),
          .specialization = specialization};
}

gpu::WhitewaterPush scene_push(const Whitewater& w, const SimulationSetup& setup) {
  gpu::WhitewaterPush p{};
  p.slots = w.slots_per_particle;
  p.owner_rows = setup.particle_texture.y;
  p.lifetime = w.lifetime;
  p.trapped_air_rate = w.trapped_air_rate;
  p.crest_rate = w.crest_rate;
  p.trapped_air_lo = w.trapped_air_range.x;
  p.trapped_air_hi = w.trapped_air_range.y;
  p.crest_lo = w.crest_range.x;
  p.crest_hi = w.crest_range.y;
  p.speed_lo = w.speed_range.x;
  p.speed_hi = w.speed_range.y;
  p.spray_density = w.spray_density;
  p.bubble_density = w.bubble_density;
  p.spray_drag = w.spray_drag;
  p.bubble_buoyancy = w.bubble_buoyancy;
  p.bubble_drag = w.bubble_drag;
  p.spawn_radius = 0.5f * setup.particle_spacing;
  return p;
}

}  // namespace

WhitewaterPass::WhitewaterPass(engine::vk::Context& context, const SolverVariant& variant, const Scene& scene,
                               const SimulationSetup& setup, const std::vector<int32_t>& specialization)
    : context_(context),
      move_(context, whitewater_pipeline(variant, "liquid.whitewater", shaders::whitewater_frag, specialization)),
      spawn_(context,
             whitewater_pipeline(variant, "liquid.whitewater_spawn", shaders::whitewater_spawn_frag, specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      push_(scene_push(scene.whitewater.value(), setup)) {
  const int64_t rows = int64_t(setup.particle_texture.y) * push_.slots;
  const uint32_t limit = context.limits().maxImageDimension2D;
  if (rows > int64_t(limit))
    throw DeviceError("whitewater: " + std::to_string(push_.slots) + " slots per particle need a texture " +
                      std::to_string(rows) + " texels tall, past the device's 2D image limit of " +
                      std::to_string(limit) + " (lower whitewater.slots_per_particle)");
  size_ = {setup.particle_texture.x, int(rows)};
  const engine::vk::ImageDesc desc{engine::vk::ImageKind::Image2D, uint32_t(size_.x), uint32_t(size_.y), 1,
                                   k_particle_format,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
  const std::vector<glm::vec4> free_slots(size_t(size_.x) * size_.y, glm::vec4(0.0f));
  for (int i = 0; i < 2; ++i) {
    positions_[i] = engine::vk::Image(context, desc, "liquid.whitewater_positions" + std::to_string(i));
    velocities_[i] = engine::vk::Image(context, desc, "liquid.whitewater_velocities" + std::to_string(i));
    engine::graph::upload_image(context, positions_[i], std::as_bytes(std::span(free_slots)));
    engine::graph::upload_image(context, velocities_[i], std::as_bytes(std::span(free_slots)));
  }
}

WhitewaterPass::Frame WhitewaterPass::import(engine::graph::RenderGraph& graph) {
  const auto pair = [&](int i) {
    return WhitewaterImages{graph.import_image(positions_[i].name(), positions_[i]),
                            graph.import_image(velocities_[i].name(), velocities_[i])};
  };
  return {pair(current_), pair(1 - current_)};
}

void WhitewaterPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                            const StepImages& step, Frame& frame, double time, float dt,
                            int64_t step_index) {
  gpu::WhitewaterPush push = push_;
  push.time = float(time);
  push.dt = dt;
  push.step = int(step_index & 0x7fffffff);
  // Every LIQUID_WHITEWATER_SPAWN_INTERVAL-th step also spawns.
  const engine::vk::GraphicsPipeline& pipeline = step_index % LIQUID_WHITEWATER_SPAWN_INTERVAL == 0 ? spawn_ : move_;
  const WhitewaterImages written = add_solver_pass<WhitewaterImages>(
      graph, pipeline, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        const VkSampler s = nearest_.handle();
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_POSITIONS, step.particles.positions, s);
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_VELOCITIES, step.particles.velocities, s);
        // Linear: liquid_velocity() filters it (the potentials fetch its texels).
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_GRID_VELOCITY, step.grids.velocity, linear_.handle());
        bindings.bind_image(b, LIQUID_BINDING_WHITEWATER_DENSITY, step.grids.density, linear_.handle());
        bindings.bind_image(b, LIQUID_BINDING_WHITEWATER_POSITIONS, frame.latest.positions, s);
        bindings.bind_image(b, LIQUID_BINDING_WHITEWATER_VELOCITIES, frame.latest.velocities, s);
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, s);
        bind_body_shapes(bindings, b, step.body_shapes, linear_);
        bind_mesh_field(bindings, b, step.mesh_field, linear_);
        return WhitewaterImages{b.write(frame.targets.positions, Access::ColorAttachmentWrite),
                                b.write(frame.targets.velocities, Access::ColorAttachmentWrite)};
      },
      [&pipeline, push](const PassContext& ctx) {
        pipeline.push_constants(ctx.cmd, push);
        engine::passes::draw_fullscreen(ctx.cmd);
      });
  frame.targets = frame.latest;
  frame.latest = written;
  current_ = 1 - current_;
}

std::vector<glm::vec4> WhitewaterPass::save() {
  const size_t texels = size_t(size_.x) * size_.y;
  std::vector<glm::vec4> out = texels_as<glm::vec4>(engine::graph::download_image(context_, positions_[current_]), texels);
  const auto velocities = texels_as<glm::vec4>(engine::graph::download_image(context_, velocities_[current_]), texels);
  out.insert(out.end(), velocities.begin(), velocities.end());
  return out;
}

void WhitewaterPass::restore(const std::vector<glm::vec4>& texels) {
  const size_t slots = size_t(size_.x) * size_.y;
  if (texels.size() != 2 * slots)
    throw ArgumentError("liquid: the checkpoint's whitewater holds " + std::to_string(texels.size() / 2) +
                        " slots; the scene has " + std::to_string(slots));
  for (size_t i = 0; i < slots; ++i) {
    const glm::vec4 p = texels[i], v = texels[slots + i];
    const float kind = p.w;
    if (!(kind == LIQUID_WHITEWATER_FREE || kind == LIQUID_WHITEWATER_SPRAY || kind == LIQUID_WHITEWATER_FOAM ||
          kind == LIQUID_WHITEWATER_BUBBLE))
      throw ArgumentError("liquid: the checkpoint's whitewater slot " + std::to_string(i) + " has no kind");
    const auto finite = [](glm::vec4 t) {
      return std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w);
    };
    if (kind != LIQUID_WHITEWATER_FREE && !(finite(p) && finite(v)))
      throw ArgumentError("liquid: the checkpoint's whitewater slot " + std::to_string(i) + " holds a non-finite value");
  }
  const auto half = [&](size_t first) { return std::as_bytes(std::span(texels).subspan(first, slots)); };
  engine::graph::upload_image(context_, positions_[current_], half(0));
  engine::graph::upload_image(context_, velocities_[current_], half(slots));
}

std::vector<WhitewaterParticle> WhitewaterPass::read(double time) {
  const size_t texels = size_t(size_.x) * size_.y;
  const auto positions = texels_as<glm::vec4>(engine::graph::download_image(context_, positions_[current_]), texels);
  const auto velocities = texels_as<glm::vec4>(engine::graph::download_image(context_, velocities_[current_]), texels);
  std::vector<WhitewaterParticle> live;
  for (size_t i = 0; i < texels; ++i) {
    const int kind = int(positions[i].w);
    if (kind == LIQUID_WHITEWATER_FREE) continue;
    WhitewaterParticle p;
    p.position = glm::vec3(positions[i]);
    p.velocity = glm::vec3(velocities[i]);
    p.kind = WhitewaterKind(kind);
    // The birth time is stored as a float, which can round to just after the double clock's time.
    p.age = float(std::max(0.0, time - double(velocities[i].w)));
    uint32_t birth_bits = 0;
    std::memcpy(&birth_bits, &velocities[i].w, sizeof birth_bits);
    p.id = (uint64_t(i) << 32) | birth_bits;
    live.push_back(p);
  }
  return live;
}

}  // namespace liquid
