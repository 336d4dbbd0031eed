#include "engine/vk/vk_helpers.h"

#include "engine/vk/context.h"
#include "engine/vk/image.h"
#include "engine/vk/vk_check.h"

namespace engine::vk {

DeviceMemory allocate_memory(Context& context, VkDeviceSize size, uint32_t type_index) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = size;
  alloc.memoryTypeIndex = type_index;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateMemory(context.device(), &alloc, nullptr, &memory));
  return {UniqueHandle<VkDeviceMemory>(context.device(), memory, vkFreeMemory), size, context.memory_counter()};
}

VkCommandBuffer allocate_command_buffer(Context& context) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = context.command_pool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(context.device(), &alloc, &cmd));
  return cmd;
}

void begin_one_time(VkCommandBuffer cmd) {
  VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
}

VkImageMemoryBarrier2 image_barrier(const Image& image, VkPipelineStageFlags2 src_stages, VkAccessFlags2 src_access,
                                    VkImageLayout old_layout, VkPipelineStageFlags2 dst_stages,
                                    VkAccessFlags2 dst_access, VkImageLayout new_layout) {
  return {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
          .srcStageMask = src_stages, .srcAccessMask = src_access,
          .dstStageMask = dst_stages, .dstAccessMask = dst_access,
          .oldLayout = old_layout, .newLayout = new_layout,
          .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .image = image.handle(), .subresourceRange = image.full_range()};
}

void cmd_image_barriers(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> barriers) {
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = static_cast<uint32_t>(barriers.size());
  dependency.pImageMemoryBarriers = barriers.data();
  vkCmdPipelineBarrier2(cmd, &dependency);
}

void cmd_copy_to_host_barrier(VkCommandBuffer cmd, VkBuffer buffer) {
  const VkBufferMemoryBarrier2 to_host{
      .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
      .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT, .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
      .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT, .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT,
      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .buffer = buffer, .size = VK_WHOLE_SIZE};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.bufferMemoryBarrierCount = 1;
  dependency.pBufferMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace engine::vk
