// Per-frame uniform data: a persistently mapped host-visible buffer split into one region per
// frame in flight. A pass copies its block in while the graph is declared and binds it by offset,
// so a frame with many steps needs no descriptor sets and no per-step buffer.
#pragma once

#include "engine/vk/buffer.h"

#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace engine::vk {

class Context;

struct UniformSlice {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
};

class UniformArena {
 public:
  // `bytes_per_frame`: the most one frame allocates; `frames_in_flight`: how many frames the GPU
  // may still be reading when a new one begins (the host waits for older ones).
  UniformArena(Context& context, VkDeviceSize bytes_per_frame, uint32_t frames_in_flight);

  // Starts the next frame's region (the region used frames_in_flight frames ago).
  void begin_frame();
  // Copies `size` bytes in and returns where they are; throws std::length_error when the frame's
  // region is full.
  UniformSlice push(const void* data, VkDeviceSize size);
  template <class T>
  UniformSlice push(const T& value) {
    return push(&value, sizeof(T));
  }
  VkDeviceSize bytes_per_frame() const { return region_size_; }

  // What one frame needs for blocks of these sizes, each pushed `repeats` times, at the largest
  // offset alignment Vulkan allows (256 bytes), so the size holds on every device.
  static VkDeviceSize frame_bytes(std::initializer_list<VkDeviceSize> block_sizes, int repeats = 1);

 private:
  Buffer buffer_;
  VkDeviceSize region_size_ = 0;
  VkDeviceSize alignment_ = 256;
  uint32_t frames_ = 1;
  uint32_t frame_ = 0;
  VkDeviceSize used_ = 0;
};

}  // namespace engine::vk
