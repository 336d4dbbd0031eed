#include "engine/vk/buffer.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_helpers.h"

#include <stdexcept>

namespace engine::vk {

Buffer::Buffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
               const std::string& name)
    : size_(size) {
  const VkDevice device = context.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
  objects_->buffer = {device, buffer, vkDestroyBuffer};
  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  uint32_t memory_type = 0;
  if (memory == MemoryUsage::HostVisible) {
    try {
      memory_type = context.find_memory_type(
          requirements.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    } catch (const std::runtime_error&) {
      memory_type = context.find_memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT);
      coherent_ = false;
    }
  } else {
    memory_type = context.find_memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  }
  objects_->memory = allocate_memory(context, requirements.size, memory_type);
  const VkDeviceMemory device_memory = objects_->memory.get();
  VK_CHECK(vkBindBufferMemory(device, buffer, device_memory, 0));
  if (memory == MemoryUsage::HostVisible) {
    void* mapped = nullptr;
    VK_CHECK(vkMapMemory(device, device_memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    mapped_ = mapped;
  }
  context.set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer), name);
}

void Buffer::flush() const {
  if (coherent_ || !mapped_) return;
  const DeviceMemory& memory = objects_->memory;
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory.get(), 0, VK_WHOLE_SIZE};
  VK_CHECK(vkFlushMappedMemoryRanges(memory.device(), 1, &range));
}

void Buffer::invalidate() const {
  if (coherent_ || !mapped_) return;
  const DeviceMemory& memory = objects_->memory;
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory.get(), 0, VK_WHOLE_SIZE};
  VK_CHECK(vkInvalidateMappedMemoryRanges(memory.device(), 1, &range));
}

}  // namespace engine::vk
