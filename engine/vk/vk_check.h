// VK_CHECK: every Vulkan call that returns a VkResult goes through it, so a failure throws with
// the call, the file, the line and the result's name instead of being ignored.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace engine::vk {

// The enumerator's name, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY" (Debian's libvulkan-dev ships no
// vk_enum_string_helper.h, so the table is ours).
const char* result_name(VkResult result);

// A failed Vulkan call. `result()` keeps the code for callers that want to branch on it.
class VulkanError : public std::runtime_error {
 public:
  VulkanError(VkResult result, const std::string& what) : std::runtime_error(what), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

[[noreturn]] void throw_vulkan_error(VkResult result, const char* call, const char* file, int line);

}  // namespace engine::vk

#define VK_CHECK(call)                                                          \
  do {                                                                          \
    const VkResult vk_check_result_ = (call);                                   \
    if (vk_check_result_ < 0)                                                   \
      ::engine::vk::throw_vulkan_error(vk_check_result_, #call, __FILE__, __LINE__); \
  } while (0)
