// RAII buffer. Host-visible buffers stay mapped for their whole life (uniform arenas, readback
// and upload staging); device-local ones are for data the GPU alone touches.
#pragma once

#include "engine/vk/device_memory.h"
#include "engine/vk/handle.h"

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

  VkBuffer handle() const { return objects_->buffer.get(); }
  VkDeviceSize size() const { return size_; }
  // Mapped pointer of a host-visible buffer (nullptr otherwise).
  void* mapped() const { return mapped_; }
  // Makes host writes visible to the device / device writes visible to the host when the memory
  // is not host-coherent.
  void flush() const;
  void invalidate() const;

 private:
  struct Objects {
    DeviceMemory memory;  // counted against the context (memory_in_use)
    UniqueHandle<VkBuffer> buffer;  // bound to memory
  };

  HandleGroup<Objects> objects_;
  ResetOnMove<VkDeviceSize> size_;
  ResetOnMove<void*> mapped_;  // unmapped by vkFreeMemory
  bool coherent_ = true;
};

}  // namespace engine::vk
