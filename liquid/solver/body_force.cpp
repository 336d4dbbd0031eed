#include "liquid/solver/body_force.h"

#include "liquid/solver/body_shapes.h"
#include "liquid/solver/solver_pass.h"
#include "liquid/solver/state.h"
#include "liquid_shader_families.h"

#include <span>

namespace liquid {

namespace {
struct BodyForcePush {
  int32_t body;
};
struct BodyExchangePush {
  int32_t body;
  float particle_mass;
};

// Both pipelines blend points into the two targets, reading the solver's block, the splat and the
// bodies; the exchange also reads the particles, the pressure force the cells' P.
engine::vk::GraphicsPipelineDesc point_reduction(const char* name, std::span<const uint32_t> vertex,
                                                 uint32_t extra_binding, uint32_t push_size,
                                                 const std::vector<int32_t>& specialization) {
  engine::vk::GraphicsPipelineDesc desc{
      .name = name,
      .vertex = vertex,
      .fragment = shader_variant(shaders::body_force_frag),
      .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
      .color_formats = {k_body_format, k_body_format},
      .blend = {engine::vk::BlendMode::Additive, engine::vk::BlendMode::Additive},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {LIQUID_BINDING_GRID_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT},
                   {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .push_constant_size = push_size,
      .specialization = specialization};
  add_body_shapes_binding(desc.bindings, VK_SHADER_STAGE_VERTEX_BIT);
  if (extra_binding != 0)
    desc.bindings.push_back({extra_binding, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT});
  return desc;
}
std::vector<int> dynamic_obstacles(const Scene& scene) {
  std::vector<int> out;
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].dynamic) out.push_back(int(i));
  return out;
}

}  // namespace

BodyForcePass::BodyForcePass(engine::vk::Context& context, const SolverVariant& variant, const Scene& scene,
                             const SimulationSetup& setup, const std::vector<int32_t>& specialization)
    : pressure_(context, point_reduction("liquid.body_force", variant.shader(shaders::body_force_vert),
                                         LIQUID_BINDING_BODY_CELL_PRESSURE, sizeof(BodyForcePush), specialization)),
      exchange_(context, point_reduction("liquid.body_exchange", variant.shader(shaders::body_exchange_vert),
                                         LIQUID_BINDING_BODY_PARTICLES, sizeof(BodyExchangePush), specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      dynamic_obstacles_(dynamic_obstacles(scene)),
      obstacles_(uint32_t(scene.obstacles.size())),
      cells_(uint32_t(variant.layout.cell_count())),
      particle_mass_(setup.particle_mass),
      projection_(variant.projection()) {}

BodyForceImages BodyForcePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                      const StepImages& step, int active) const {
  const engine::vk::ImageDesc desc{engine::vk::ImageKind::Image2D, 1, obstacles_, 1, k_body_format, 0};
  BodyForceImages out{graph.create_image("liquid.body_force", desc), graph.create_image("liquid.body_torque", desc)};
  // Per body its pressure, then its exchange, adding into the targets the first pass clears. Under
  // the projection the pressure carries what the body's motion asks of the liquid: no exchange.
  bool first = true;
  for (const int body : dynamic_obstacles_)
    for (const bool exchange : {false, true}) {
      if (exchange && projection_) continue;
      const engine::graph::AttachmentOptions start =
          first ? engine::graph::clear_to(0, 0, 0, 0) : engine::graph::AttachmentOptions{engine::graph::LoadOp::Load, {}};
      first = false;
      const engine::vk::GraphicsPipeline& pipeline = exchange ? exchange_ : pressure_;
      out = add_solver_pass<BodyForceImages>(
          graph, pipeline, uniforms,
          [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
            const VkSampler s = nearest_.handle();
            bindings.bind_image(b, LIQUID_BINDING_GRID_SPLAT, step.splat, s);
            bindings.bind_image(b, LIQUID_BINDING_BODIES, step.bodies, s);
            bind_body_shapes(bindings, b, step.body_shapes, linear_);
            if (exchange) bindings.bind_image(b, LIQUID_BINDING_BODY_PARTICLES, step.particles.positions, s);
            // The equation of state's P, or the projection's last iteration.
            const ImageHandle pressure = projection_ ? step.pressure.phi : step.pressure.pressure;
            if (!exchange) bindings.bind_image(b, LIQUID_BINDING_BODY_CELL_PRESSURE, pressure, s);
            return BodyForceImages{b.write(out.force, Access::ColorAttachmentBlend, start),
                                   b.write(out.torque, Access::ColorAttachmentBlend, start)};
          },
          [this, &pipeline, body, exchange, active](const PassContext& ctx) {
            if (!exchange) {
              pipeline.push_constants(ctx.cmd, BodyForcePush{body});
              vkCmdDraw(ctx.cmd, cells_, 1, 0, 0);  // a point per grid cell
            } else if (active > 0) {
              pipeline.push_constants(ctx.cmd, BodyExchangePush{body, particle_mass_});
              vkCmdDraw(ctx.cmd, uint32_t(active), 1, 0, 0);  // a point per particle
            }
          });
    }
  return out;
}

}  // namespace liquid
