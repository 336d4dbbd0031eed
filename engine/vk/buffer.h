// RAII buffer. Host-visible buffers stay mapped for their whole life (uniform arenas, readback
// and upload staging); device-local ones are for data the GPU alone touches.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <string>

namespace engine::vk {

class Context;

enum class MemoryUsage { DeviceLocal, HostVisible };

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
         const std::string& name);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  // Mapped pointer of a host-visible buffer (nullptr otherwise).
  void* mapped() const { return mapped_; }
  // Makes host writes visible to the device / device writes visible to the host when the memory
  // is not host-coherent.
  void flush() const;
  void invalidate() const;

 private:
  void release();

  Context* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  bool coherent_ = true;
};

}  // namespace engine::vk
