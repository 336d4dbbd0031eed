// Move-only owners of Vulkan objects, so the classes that hold them need no hand-written move,
// move assignment or destroy code (rule of zero).
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace engine::vk {

// Owns one object of a device and destroys it with the matching vkDestroy* / vkFreeMemory call.
// Empty when default-constructed or moved from.
template <class T>
class UniqueHandle {
 public:
  using Destroy = void(VKAPI_PTR*)(VkDevice, T, const VkAllocationCallbacks*);

  UniqueHandle() = default;
  UniqueHandle(VkDevice device, T handle, Destroy destroy) noexcept
      : device_(device), handle_(handle), destroy_(destroy) {}
  ~UniqueHandle() { reset(); }
  UniqueHandle(UniqueHandle&& other) noexcept
      : device_(other.device_), handle_(other.release()), destroy_(other.destroy_) {}
  UniqueHandle& operator=(UniqueHandle&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      destroy_ = other.destroy_;
      handle_ = other.release();
    }
    return *this;
  }

  T get() const { return handle_; }
  VkDevice device() const { return device_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
  // Gives the object up without destroying it.
  T release() noexcept { return std::exchange(handle_, VK_NULL_HANDLE); }
  // Destroys the object, if any, and leaves the handle empty.
  void reset() noexcept {
    if (handle_ != VK_NULL_HANDLE) destroy_(device_, release(), nullptr);
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_ = VK_NULL_HANDLE;
  Destroy destroy_ = nullptr;
};

// A struct of UniqueHandles declared parent first (memory, the image bound to it, its views),
// released child first on destruction and when a new value is moved in: a defaulted member-wise
// move assignment would release the old parent before its children.
template <class T>
class HandleGroup {
 public:
  HandleGroup() = default;
  HandleGroup(HandleGroup&&) noexcept = default;
  HandleGroup& operator=(HandleGroup&& other) noexcept {
    if (this != &other) {
      T old = std::move(value_);  // released at the end of this block, last member first
      value_ = std::move(other.value_);
    }
    return *this;
  }

  T* operator->() { return &value_; }
  const T* operator->() const { return &value_; }

 private:
  T value_{};
};

// A plain value (a size, a mapped pointer) that a move resets to T{}, so a moved-from owner reads
// as empty.
template <class T>
class ResetOnMove {
 public:
  ResetOnMove() = default;
  ResetOnMove(T value) : value_(value) {}
  ResetOnMove(ResetOnMove&& other) noexcept : value_(std::exchange(other.value_, T{})) {}
  ResetOnMove& operator=(ResetOnMove&& other) noexcept {
    value_ = std::exchange(other.value_, T{});
    return *this;
  }

  T get() const { return value_; }
  operator T() const { return value_; }

 private:
  T value_{};
};

}  // namespace engine::vk
