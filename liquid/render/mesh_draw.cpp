#include "liquid/render/mesh_draw.h"

#include "engine/passes/bindings.h"
#include "liquid/physics/mesh.h"
#include "liquid/solver/gpu_types.h"
#include "liquid/solver/images.h"
#include "liquid/solver/mesh_field.h"
#include "liquid_shader_families.h"

namespace liquid {

MeshDrawPass::MeshDrawPass(engine::vk::Context& context, const LiquidNode& node, VkFormat color_format,
                           VkFormat depth_format)
    : node_(node), nearest_(context, VK_FILTER_NEAREST) {
  const Scene& scene = node.scene();
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].shape == ObstacleShape::Mesh)
      meshes_.push_back({i, mesh_triangle_texture(context, scene.obstacles[i].mesh, "liquid.draw_triangles" + std::to_string(i)),
                         uint32_t(scene.obstacles[i].mesh.indices.size() / 3)});
  if (meshes_.empty()) return;
  pipeline_ = engine::vk::GraphicsPipeline(
      context, engine::vk::GraphicsPipelineDesc{
                   .name = "liquid.mesh_draw",
                   .vertex = shader_variant(shaders::mesh_draw_vert),
                   .fragment = shader_variant(shaders::mesh_draw_frag),
                   .color_formats = {color_format},
                   .depth_format = depth_format,
                   .depth_test = true,
                   .depth_write = true,
                   .bindings = {{LIQUID_BINDING_MESH_TRIANGLES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
                   .push_constant_size = sizeof(gpu::MeshDrawPush)});
}

MeshDrawPass::Targets MeshDrawPass::add_to(engine::graph::RenderGraph& graph, Targets targets,
                                           const glm::mat4& view_projection, VkRect2D viewport,
                                           glm::vec3 sun_direction) {
  struct Data {
    std::vector<engine::passes::PassBindings> bindings;  // one per mesh
    std::vector<gpu::MeshDrawPush> pushes;
    Targets out;
  };
  const std::vector<ObstaclePose> poses = node_.obstacle_poses(node_.time());
  return graph
      .add_pass<Data>(
          "liquid.mesh_draw",
          [&](PassBuilder& b, Data& d) {
            for (Mesh& m : meshes_) {
              d.bindings.emplace_back(pipeline_);
              d.bindings.back().bind_image(b, LIQUID_BINDING_MESH_TRIANGLES,
                                           graph.import_image(m.triangles.name(), m.triangles), nearest_.handle());
              const glm::mat4 model = mesh_to_world(node_.scene().obstacles[m.obstacle].mesh, poses[m.obstacle].center,
                                                    poses[m.obstacle].orientation);
              gpu::MeshDrawPush push{};
              push.view_projection = view_projection;
              const glm::mat4 rows = glm::transpose(model);
              for (int r = 0; r < 3; ++r) push.model_rows[r] = rows[r];
              push.sun_direction = glm::vec4(sun_direction, 0.0f);
              d.pushes.push_back(push);
            }
            d.out.color = b.write(targets.color, Access::ColorAttachmentWrite, engine::graph::clear_to(0, 0, 0, 1));
            d.out.depth = b.write(targets.depth, Access::DepthAttachmentWrite, engine::graph::clear_depth(1.0f));
          },
          [this, viewport](PassContext& ctx, const Data& d) {
            for (size_t k = 0; k < meshes_.size(); ++k) {
              d.bindings[k].bind_and_push(ctx);
              const VkViewport v{float(viewport.offset.x), float(viewport.offset.y), float(viewport.extent.width),
                                 float(viewport.extent.height), 0.0f, 1.0f};
              vkCmdSetViewport(ctx.cmd, 0, 1, &v);
              vkCmdSetScissor(ctx.cmd, 0, 1, &viewport);
              pipeline_.push_constants(ctx.cmd, d.pushes[k]);
              vkCmdDraw(ctx.cmd, 3 * meshes_[k].triangle_count, 1, 0, 0);
            }
          })
      .out;
}

}  // namespace liquid
