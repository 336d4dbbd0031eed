// Small Vulkan steps that the engine's objects, the render graph and the tools each took in full:
// device memory for a buffer or image, a command buffer from the context's pool, whole-image and
// to-host barriers. Internal: not installed.
#pragma once

#include "engine/vk/device_memory.h"
#include "engine/vk/handle.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

namespace engine::vk {

class Context;
class Image;

// `size` bytes of the memory type `type_index`, freed with the returned object and counted against
// the context's memory_in_use() while it lives.
DeviceMemory allocate_memory(Context& context, VkDeviceSize size, uint32_t type_index);

// A primary command buffer from the context's pool; the caller frees it with vkFreeCommandBuffers.
VkCommandBuffer allocate_command_buffer(Context& context);

// Resets `cmd` and begins it for one submission.
void begin_one_time(VkCommandBuffer cmd);

// A barrier of the whole of `image` (all its mips, layers and aspects), with no queue family transfer.
VkImageMemoryBarrier2 image_barrier(const Image& image, VkPipelineStageFlags2 src_stages, VkAccessFlags2 src_access,
                                    VkImageLayout old_layout, VkPipelineStageFlags2 dst_stages,
                                    VkAccessFlags2 dst_access, VkImageLayout new_layout);

// The image barriers in one vkCmdPipelineBarrier2.
void cmd_image_barriers(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> barriers);

// A copy's writes to `buffer` made visible to the host, which reads it after the submission's fence.
void cmd_copy_to_host_barrier(VkCommandBuffer cmd, VkBuffer buffer);

}  // namespace engine::vk
