#include "liquid/solver/body_grid.h"

#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/solver/state.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

namespace liquid {

namespace {
struct BodyGridPush {
  int32_t excluded;
};
}  // namespace

BodyGridPass::BodyGridPass(engine::vk::Context& context, const GridLayout& layout,
                           const std::vector<int32_t>& specialization)
    : pipeline_(context,
                engine::vk::GraphicsPipelineDesc{
                    .name = "liquid.body_grid",
                    .vertex = grid_pass_shaders(layout).vertex,
                    .geometry = grid_pass_shaders(layout).geometry,
                    .fragment = layout.pick(liquid_shaders::body_grid_frag_2d, liquid_shaders::body_grid_frag_3d,
                                            liquid_shaders::body_grid_frag_3d_atlas),
                    .color_formats = {k_grid_velocity_format},
                    .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                 {LIQUID_BINDING_GRID_SPLAT, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {LIQUID_BINDING_BODIES, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                    .push_constant_size = sizeof(BodyGridPush),
                    .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      desc_(layout.image_desc(k_grid_velocity_format, 0)) {}

ImageHandle BodyGridPass::add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                 ImageHandle splat, ImageHandle bodies, int body) const {
  const ImageHandle target = graph.create_image("liquid.body_grid_velocity", desc_);
  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle out;
  };
  return graph
      .add_pass<Data>(
          "liquid.body_grid",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_GRID_SPLAT, splat, nearest_.handle());
            d.bindings.bind_image(b, LIQUID_BINDING_BODIES, bodies, nearest_.handle());
            d.out = b.write(target, Access::ColorAttachmentWrite);
          },
          [this, body](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            pipeline_.push_constants(ctx.cmd, BodyGridPush{body});
            engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
          })
      .out;
}

}  // namespace liquid
