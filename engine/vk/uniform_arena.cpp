#include "engine/vk/uniform_arena.h"

#include "engine/vk/context.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace engine::vk {

namespace {
VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }
}  // namespace

UniformArena::UniformArena(Context& context, VkDeviceSize bytes_per_frame, uint32_t frames_in_flight)
    : alignment_(std::max<VkDeviceSize>(context.limits().minUniformBufferOffsetAlignment, 16)),
      frames_(std::max(frames_in_flight, 1u)) {
  region_size_ = align_up(bytes_per_frame, alignment_);
  buffer_ = Buffer(context, region_size_ * frames_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::HostVisible,
                   "uniform_arena");
  frame_ = frames_ - 1;
}

VkDeviceSize UniformArena::frame_bytes(std::initializer_list<VkDeviceSize> block_sizes, int repeats) {
  constexpr VkDeviceSize k_max_offset_alignment = 256;  // the spec's bound on minUniformBufferOffsetAlignment
  VkDeviceSize bytes = 0;
  for (VkDeviceSize size : block_sizes) bytes += align_up(size, k_max_offset_alignment);
  return bytes * VkDeviceSize(std::max(repeats, 1));
}

void UniformArena::begin_frame() {
  frame_ = (frame_ + 1) % frames_;
  used_ = 0;
}

UniformSlice UniformArena::push(const void* data, VkDeviceSize size) {
  const VkDeviceSize offset = align_up(used_, alignment_);
  if (offset + size > region_size_)
    throw std::length_error("uniform arena: a frame needs more than its " + std::to_string(region_size_) +
                            " bytes (too many steps in one frame?)");
  const VkDeviceSize absolute = VkDeviceSize(frame_) * region_size_ + offset;
  std::memcpy(static_cast<char*>(buffer_.mapped()) + absolute, data, size);
  buffer_.flush();
  used_ = offset + size;
  return {buffer_.handle(), absolute, size};
}

}  // namespace engine::vk
