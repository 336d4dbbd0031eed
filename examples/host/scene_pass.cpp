#include "scene_pass.h"

#include "engine/vk/context.h"
#include "host_shaders.h"

namespace {

struct ScenePush {
  glm::mat4 view_projection;
  glm::mat4 model;
};
static_assert(sizeof(ScenePush) <= 128, "push constants: lavapipe allows 128 bytes");

constexpr uint32_t k_floor_vertices = 6;
constexpr uint32_t k_box_vertices = 36;  // 6 faces of 2 triangles

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

ScenePass::ScenePass(engine::vk::Context& context)
    : pipeline_(context, engine::vk::GraphicsPipelineDesc{.name = "host.scene",
                                                         .vertex = host_shaders::scene_vert,
                                                         .fragment = host_shaders::scene_frag,
                                                         .color_formats = {k_color_format},
                                                         .depth_format = k_depth_format,
                                                         .depth_test = true,
                                                         .depth_write = true,
                                                         .depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL,
                                                         .push_constant_size = sizeof(ScenePush)}) {}

void ScenePass::record(VkCommandBuffer cmd, engine::vk::Image& color, engine::vk::Image& depth,
                       const glm::mat4& view_projection, const glm::mat4& floor_model, const glm::mat4& box_model) const {
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
  pipeline_.push_constants(cmd, ScenePush{view_projection, floor_model});
  vkCmdDraw(cmd, k_floor_vertices, 1, 0, 0);
  pipeline_.push_constants(cmd, ScenePush{view_projection, box_model});
  vkCmdDraw(cmd, k_box_vertices, 1, k_floor_vertices, 0);
  vkCmdEndRendering(cmd);

  // Where this pass leaves the targets: the graph's first use of them waits for these writes.
  color.sync_state() = engine::vk::ImageSyncState::after_write(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, k_color_stage,
                                                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  depth.sync_state() =
      engine::vk::ImageSyncState::after_write(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, k_depth_stages, k_depth_access);
}
