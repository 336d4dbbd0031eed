#include "scene_pass.h"

#include "engine/vk/context.h"
#include "host_shaders.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

struct ScenePush {
  glm::mat4 view_projection;
  glm::mat4 model;
};
static_assert(sizeof(ScenePush) <= 128, "push constants: lavapipe allows 128 bytes");

constexpr uint32_t k_vertex_binding = 0;

// A barrier from wherever the graph (or the previous frame) left `image` to `layout` for `stages`.
VkImageMemoryBarrier2 to_attachment(engine::vk::Image& image, VkImageLayout layout, VkPipelineStageFlags2 stages,
                                    VkAccessFlags2 access) {
  const engine::vk::ImageSyncState& s = image.sync_state();
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = s.write_stages | s.read_stages;
  b.srcAccessMask = s.write_access;
  b.dstStageMask = stages;
  b.dstAccessMask = access;
  b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // cleared: the old contents are not needed
  b.newLayout = layout;
  b.image = image.handle();
  b.subresourceRange = image.full_range();
  return b;
}

}  // namespace

struct ScenePass::Buffers {
  std::vector<HostVertex> vertices;  // padded to scene.vert's whole array (the uniform block's size)
  std::vector<uint32_t> indices;
  Range floor, paddle;

  Range append(const HostMesh& mesh) {
    const Range range{uint32_t(indices.size()), uint32_t(mesh.indices.size()), int32_t(vertices.size())};
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    return range;
  }
  Buffers(const HostMesh& floor_mesh, const HostMesh& paddle_mesh)
      : floor(append(floor_mesh)), paddle(append(paddle_mesh)) {
    if (vertices.size() > k_max_vertices)
      throw std::invalid_argument("the host's meshes have more than " + std::to_string(k_max_vertices) + " vertices");
    vertices.resize(k_max_vertices);
  }
};

ScenePass::ScenePass(engine::vk::Context& context, const HostVulkan& vulkan, const HostMesh& floor,
                     const HostMesh& paddle)
    : ScenePass(context, vulkan, Buffers(floor, paddle)) {}

ScenePass::ScenePass(engine::vk::Context& context, const HostVulkan& vulkan, const Buffers& buffers)
    : pipeline_(context, engine::vk::GraphicsPipelineDesc{.name = "host.scene",
                                                         .vertex = host_shaders::scene_vert,
                                                         .fragment = host_shaders::scene_frag,
                                                         .color_formats = {k_color_format},
                                                         .depth_format = k_depth_format,
                                                         .depth_test = true,
                                                         .depth_write = true,
                                                         .depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL,
                                                         .bindings = {{k_vertex_binding,
                                                                       engine::vk::DescriptorKind::UniformBuffer,
                                                                       VK_SHADER_STAGE_VERTEX_BIT}},
                                                         .push_constant_size = sizeof(ScenePush)}),
      vertices_(vulkan.physical_device, vulkan.device, buffers.vertices.data(),
                buffers.vertices.size() * sizeof(HostVertex), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      indices_(vulkan.physical_device, vulkan.device, buffers.indices.data(), buffers.indices.size() * sizeof(uint32_t),
               VK_BUFFER_USAGE_INDEX_BUFFER_BIT),
      floor_(buffers.floor),
      paddle_(buffers.paddle) {}

void ScenePass::record(VkCommandBuffer cmd, engine::vk::Image& color, engine::vk::Image& depth,
                       const glm::mat4& view_projection, const glm::mat4& floor_model,
                       const glm::mat4& paddle_model) const {
  constexpr VkPipelineStageFlags2 k_color_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  constexpr VkPipelineStageFlags2 k_depth_stages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkAccessFlags2 k_depth_access =
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  const VkImageMemoryBarrier2 barriers[] = {
      to_attachment(color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, k_color_stage,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT),
      to_attachment(depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, k_depth_stages, k_depth_access)};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 2;
  dependency.pImageMemoryBarriers = barriers;
  vkCmdPipelineBarrier2(cmd, &dependency);

  const uint32_t width = color.desc().width, height = color.desc().height;
  VkRenderingAttachmentInfo color_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color_attachment.imageView = color.attachment_view();
  color_attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color_attachment.clearValue.color = {{0.45f, 0.6f, 0.85f, 1.0f}};  // the host's sky, in radiance
  VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth_attachment.imageView = depth.attachment_view();
  depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth_attachment.clearValue.depthStencil = {0.0f, 0};  // reversed Z: 0 is the far plane
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {width, height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color_attachment;
  rendering.pDepthAttachment = &depth_attachment;
  vkCmdBeginRendering(cmd, &rendering);
  pipeline_.bind(cmd, width, height);
  pipeline_.push_uniform(cmd, k_vertex_binding, vertices_.buffer, 0, vertices_.size);
  vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
  for (const auto& [range, model] : {std::pair{floor_, floor_model}, std::pair{paddle_, paddle_model}}) {
    pipeline_.push_constants(cmd, ScenePush{view_projection, model});
    vkCmdDrawIndexed(cmd, range.index_count, 1, range.first_index, range.vertex_offset, 0);
  }
  vkCmdEndRendering(cmd);

  // Where this pass leaves the targets: the graph's first use of them waits for these writes.
  color.sync_state() = engine::vk::ImageSyncState::after_write(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, k_color_stage,
                                                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  depth.sync_state() =
      engine::vk::ImageSyncState::after_write(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, k_depth_stages, k_depth_access);
}
