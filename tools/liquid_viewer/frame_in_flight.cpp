#include "tools/liquid_viewer/frame_in_flight.h"

#include "engine/io/png.h"
#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

#include <cstring>

namespace viewer {

FrameSlot::FrameSlot(engine::vk::Context& context) : graph(&context), context_(context) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = context.command_pool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(context.device(), &alloc, &cmd));
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VK_CHECK(vkCreateFence(context.device(), &fence_info, nullptr, &fence));
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vkCreateSemaphore(context.device(), &semaphore, nullptr, &acquired));
}

FrameSlot::~FrameSlot() {
  vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX);
  vkDestroySemaphore(context_.device(), acquired, nullptr);
  vkDestroyFence(context_.device(), fence, nullptr);
  vkFreeCommandBuffers(context_.device(), context_.command_pool(), 1, &cmd);
}

void FrameSlot::wait() {
  VK_CHECK(vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  if (!shot) return;
  shot->buffer->invalidate();
  engine::vk::Rgba8Image picture;
  picture.width = shot->width;
  picture.height = shot->height;
  picture.pixels.resize(size_t(shot->width) * shot->height * 4);
  std::memcpy(picture.pixels.data(), shot->buffer->mapped(), picture.pixels.size());
  if (shot->bgra)
    for (size_t i = 0; i < picture.pixels.size(); i += 4) std::swap(picture.pixels[i], picture.pixels[i + 2]);
  for (size_t i = 3; i < picture.pixels.size(); i += 4) picture.pixels[i] = 255;  // the window is opaque
  const std::filesystem::path path = shot->path;
  shot.reset();
  engine::vk::write_png(path, picture);
}

VkCommandBuffer FrameSlot::begin() {
  VK_CHECK(vkResetFences(context_.device(), 1, &fence));
  VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  return cmd;
}

void transition(VkCommandBuffer cmd, engine::vk::Image& image, VkImageLayout layout, VkPipelineStageFlags2 stages,
                VkAccessFlags2 access, bool writes) {
  engine::vk::ImageSyncState& state = image.sync_state();
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.srcStageMask = state.write_stages | state.read_stages;
  barrier.srcAccessMask = state.write_access;
  barrier.dstStageMask = stages;
  barrier.dstAccessMask = access;
  barrier.oldLayout = state.layout;
  barrier.newLayout = layout;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.handle();
  barrier.subresourceRange = image.full_range();
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
  state = writes ? engine::vk::ImageSyncState::after_write(layout, stages, access)
                 : engine::vk::ImageSyncState::after_read(layout, stages, access);
}

Shot copy_to_buffer(engine::vk::Context& context, VkCommandBuffer cmd, engine::vk::Image& image, bool bgra,
                    const std::filesystem::path& path) {
  const engine::vk::ImageDesc& d = image.desc();
  Shot shot;
  shot.width = d.width;
  shot.height = d.height;
  shot.bgra = bgra;
  shot.path = path;
  shot.buffer = std::make_shared<engine::vk::Buffer>(context, VkDeviceSize(d.width) * d.height * 4,
                                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                     engine::vk::MemoryUsage::HostVisible, "viewer.screenshot");
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {d.width, d.height, 1};
  vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, shot.buffer->handle(), 1, &region);
  // The host reads the buffer after the fence: a buffer barrier to HOST makes the copy visible.
  VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = shot.buffer->handle();
  barrier.size = VK_WHOLE_SIZE;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.bufferMemoryBarrierCount = 1;
  dependency.pBufferMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
  return shot;
}

}  // namespace viewer
