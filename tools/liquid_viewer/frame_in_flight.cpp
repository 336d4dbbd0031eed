#include "tools/liquid_viewer/frame_in_flight.h"

#include "engine/io/png.h"
#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_helpers.h"

#include <cstring>

namespace viewer {

FrameSlot::FrameSlot(engine::vk::Context& context) : graph(&context), context_(context) {
  cmd = engine::vk::allocate_command_buffer(context);
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
  engine::vk::begin_one_time(cmd);
  return cmd;
}

void transition(VkCommandBuffer cmd, engine::vk::Image& image, VkImageLayout layout, VkPipelineStageFlags2 stages,
                VkAccessFlags2 access, bool writes) {
  engine::vk::ImageSyncState& state = image.sync_state();
  const VkImageMemoryBarrier2 barrier = engine::vk::image_barrier(
      image, state.write_stages | state.read_stages, state.write_access, state.layout, stages, access, layout);
  engine::vk::cmd_image_barriers(cmd, {&barrier, 1});
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
  engine::vk::cmd_copy_to_host_barrier(cmd, shot.buffer->handle());
  return shot;
}

}  // namespace viewer
