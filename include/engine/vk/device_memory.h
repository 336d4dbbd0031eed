// Device memory that counts itself against its Context: every buffer and image the engine
// allocates holds one, so Context::memory_in_use() and memory_peak() say how much device memory
// the engine's objects (a node's state, its passes' transients, a renderer's targets) hold.
#pragma once

#include "engine/vk/handle.h"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace engine::vk {

// Bytes held now and the most held at once since the last reset_peak().
class MemoryCounter {
 public:
  void add(VkDeviceSize bytes) {
    const VkDeviceSize now = in_use_.fetch_add(bytes) + bytes;
    VkDeviceSize peak = peak_.load();
    while (now > peak && !peak_.compare_exchange_weak(peak, now)) {
    }
  }
  void remove(VkDeviceSize bytes) noexcept { in_use_.fetch_sub(bytes); }
  VkDeviceSize in_use() const { return in_use_.load(); }
  VkDeviceSize peak() const { return peak_.load(); }
  void reset_peak() { peak_.store(in_use_.load()); }

 private:
  std::atomic<VkDeviceSize> in_use_{0};
  std::atomic<VkDeviceSize> peak_{0};
};

// One vkAllocateMemory, freed (and taken off its counter) when destroyed.
class DeviceMemory {
 public:
  DeviceMemory() = default;
  DeviceMemory(UniqueHandle<VkDeviceMemory> memory, VkDeviceSize size, MemoryCounter& counter)
      : memory_(std::move(memory)), size_(size), counter_(&counter) {
    counter_->add(size_);
  }
  ~DeviceMemory() { reset(); }
  DeviceMemory(DeviceMemory&& other) noexcept
      : memory_(std::move(other.memory_)), size_(std::exchange(other.size_, 0)),
        counter_(std::exchange(other.counter_, nullptr)) {}
  DeviceMemory& operator=(DeviceMemory&& other) noexcept {
    if (this != &other) {
      reset();
      memory_ = std::move(other.memory_);
      size_ = std::exchange(other.size_, 0);
      counter_ = std::exchange(other.counter_, nullptr);
    }
    return *this;
  }

  VkDeviceMemory get() const { return memory_.get(); }
  VkDevice device() const { return memory_.device(); }
  VkDeviceSize size() const { return size_; }
  explicit operator bool() const { return bool(memory_); }
  void reset() noexcept {
    if (counter_) counter_->remove(size_);
    memory_.reset();
    size_ = 0;
    counter_ = nullptr;
  }

 private:
  UniqueHandle<VkDeviceMemory> memory_;
  VkDeviceSize size_ = 0;
  MemoryCounter* counter_ = nullptr;
};

}  // namespace engine::vk
