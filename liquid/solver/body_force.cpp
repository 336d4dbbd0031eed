#include "liquid/solver/body_force.h"

#include "engine/passes/bindings.h"
#include "liquid/solver/body_shapes.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

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
      .fragment = liquid_shaders::body_force_frag,
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
}  // namespace

BodyForcePass::BodyForcePass(engine::vk::Context& context, const GridLayout& layout, int obstacles,
                             float particle_mass, const std::vector<int32_t>& specialization)
    : pressure_(context, point_reduction("liquid.body_force",
                                         layout.pick(liquid_shaders::body_force_vert_2d, liquid_shaders::body_force_vert_3d,
                                                     liquid_shaders::body_force_vert_3d_atlas),
                                         LIQUID_BINDING_BODY_CELL_PRESSURE, sizeof(BodyForcePush), specialization)),
      exchange_(context, point_reduction("liquid.body_exchange",
                                         layout.pick(liquid_shaders::body_exchange_vert_2d,
                                                     liquid_shaders::body_exchange_vert_3d,
                                                     liquid_shaders::body_exchange_vert_3d_atlas),
                                         LIQUID_BINDING_BODY_PARTICLES, sizeof(BodyExchangePush), specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      obstacles_(uint32_t(obstacles)),
      cells_(uint32_t(layout.cell_count())),
      particle_mass_(particle_mass) {}

BodyForceImages BodyForcePass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                      ImageHandle splat, ImageHandle cell_pressure, ImageHandle positions, int active,
                                      ImageHandle bodies, ImageHandle body_shapes,
                                      const std::vector<int>& dynamic_obstacles) const {
  const engine::vk::ImageDesc desc{engine::vk::ImageKind::Image2D, 1, obstacles_, 1, k_body_format, 0};
  BodyForceImages out{graph.create_image("liquid.body_force", desc), graph.create_image("liquid.body_torque", desc)};
  // Per body its pressure, then its exchange, adding into the targets the first pass clears.
  bool first = true;
  for (const int body : dynamic_obstacles)
    for (const bool exchange : {false, true}) {
      const engine::graph::AttachmentOptions start =
          first ? engine::graph::clear_to(0, 0, 0, 0) : engine::graph::AttachmentOptions{engine::graph::LoadOp::Load, {}};
      first = false;
      const engine::vk::GraphicsPipeline& pipeline = exchange ? exchange_ : pressure_;
      struct Data {
        engine::passes::PassBindings bindings;
        BodyForceImages out;
      };
      out = graph
                .add_pass<Data>(
                    exchange ? "liquid.body_exchange" : "liquid.body_force",
                    [&](PassBuilder& b, Data& d) {
                      const VkSampler s = nearest_.handle();
                      d.bindings = engine::passes::PassBindings(pipeline);
                      d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
                      d.bindings.bind_image(b, LIQUID_BINDING_GRID_SPLAT, splat, s);
                      d.bindings.bind_image(b, LIQUID_BINDING_BODIES, bodies, s);
                      bind_body_shapes(d.bindings, b, body_shapes, linear_);
                      if (exchange) d.bindings.bind_image(b, LIQUID_BINDING_BODY_PARTICLES, positions, s);
                      if (!exchange) d.bindings.bind_image(b, LIQUID_BINDING_BODY_CELL_PRESSURE, cell_pressure, s);
                      d.out.force = b.write(out.force, Access::ColorAttachmentBlend, start);
                      d.out.torque = b.write(out.torque, Access::ColorAttachmentBlend, start);
                    },
                    [this, &pipeline, body, exchange, active](PassContext& ctx, const Data& d) {
                      d.bindings.bind_and_push(ctx);
                      if (!exchange) {
                        pipeline.push_constants(ctx.cmd, BodyForcePush{body});
                        vkCmdDraw(ctx.cmd, cells_, 1, 0, 0);  // a point per grid cell
                      } else if (active > 0) {
                        pipeline.push_constants(ctx.cmd, BodyExchangePush{body, particle_mass_});
                        vkCmdDraw(ctx.cmd, uint32_t(active), 1, 0, 0);  // a point per particle
                      }
                    })
                .out;
    }
  return out;
}

}  // namespace liquid
