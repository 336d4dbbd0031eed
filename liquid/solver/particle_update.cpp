#include "liquid/solver/particle_update.h"

#include "engine/passes/fullscreen.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/solver_pass.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/state.h"
#include "liquid_shader_families.h"

#include <utility>

namespace liquid {

namespace {

std::vector<engine::vk::DescriptorBinding> particle_bindings(const SolverVariant& variant) {
  std::vector<engine::vk::DescriptorBinding> bindings{
      {LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
      {LIQUID_BINDING_PARTICLE_POSITIONS, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_VELOCITIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_GRID_VELOCITY, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_DEPOSIT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_PARTICLE_DEPOSIT_UPPER, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
      {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}};
  if (variant.projection())
    bindings.push_back({LIQUID_BINDING_PARTICLE_CORRECTION, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  add_body_shapes_binding(bindings, VK_SHADER_STAGE_FRAGMENT_BIT);
  add_mesh_field_binding(variant.meshes, bindings);
  return bindings;
}

// Position and velocity, and C_p under the affine transfer.
std::vector<VkFormat> particle_formats(const SolverVariant& variant) {
  return std::vector<VkFormat>(size_t(2 + variant.affine_textures()), k_particle_format);
}

// The scene's constants and the pass's own: whether it runs the position correction.
std::vector<int32_t> particle_specialization(const SolverVariant& variant, std::vector<int32_t> constants) {
  static_assert(LIQUID_PARTICLE_POSITION_CORRECTION_ID == specialization_id::count,
                "the particle pass's constant follows the scene's");
  constants.resize(specialization_id::count);
  constants.push_back(variant.position_correction ? 1 : 0);
  return constants;
}

}  // namespace

ParticleUpdatePass::ParticleUpdatePass(engine::vk::Context& context, const SolverVariant& variant,
                                       const std::vector<int32_t>& specialization)
    : pipeline_(context, engine::vk::GraphicsPipelineDesc{.name = "liquid.particle",
                                                          .vertex = engine::passes::fullscreen_vertex_shader(),
                                                          .fragment = variant.shader(shaders::particle_frag),
                                                          .color_formats = particle_formats(variant),
                                                          .bindings = particle_bindings(variant),
                                                          .specialization = particle_specialization(variant, specialization)}),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      variant_(variant) {}

void ParticleUpdatePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                StepImages& step, int active_after) const {
  step.particle_targets = add_solver_pass<ParticleImages>(
      graph, pipeline_, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        const VkSampler s = nearest_.handle();
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_POSITIONS, step.particles.positions, s);
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_VELOCITIES, step.particles.velocities, s);
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_SPLAT, step.splat, s);
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_GRID_VELOCITY, step.grids.velocity, s);
        // The position correction's deposit; without it the splat stands in, unread.
        const bool correct = variant_.position_correction;
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_DEPOSIT, correct ? step.deposit : step.splat, s);
        bindings.bind_image(b, LIQUID_BINDING_PARTICLE_DEPOSIT_UPPER,
                            correct && step.deposit_upper.valid() ? step.deposit_upper : step.splat, s);
        bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, s);
        if (variant_.projection()) bindings.bind_image(b, LIQUID_BINDING_PARTICLE_CORRECTION, step.grids.correction, s);
        bind_body_shapes(bindings, b, step.body_shapes, linear_);
        bind_mesh_field(bindings, b, step.mesh_field, linear_);
        ParticleImages written{b.write(step.particle_targets.positions, Access::ColorAttachmentWrite),
                               b.write(step.particle_targets.velocities, Access::ColorAttachmentWrite)};
        for (size_t a = 0; a < written.affine.size(); ++a)
          if (step.particle_targets.affine[a].valid())
            written.affine[a] = b.write(step.particle_targets.affine[a], Access::ColorAttachmentWrite);
        return written;
      },
      [active_after](const PassContext& ctx) {
        if (active_after == 0) return;
        // Only the rows that hold active (or newly emitted) particles are shaded.
        const uint32_t rows = (uint32_t(active_after) + ctx.width - 1) / ctx.width;
        const VkRect2D scissor{{0, 0}, {ctx.width, rows}};
        vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
        engine::passes::draw_fullscreen(ctx.cmd);
      });
  std::swap(step.particles, step.particle_targets);
}

}  // namespace liquid
