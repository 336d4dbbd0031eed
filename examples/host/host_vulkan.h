// The host's own Vulkan objects, made with plain Vulkan as an engine would: an instance (with the
// validation layer and synchronization validation when asked), a device that enables what the
// liquid library needs (engine/vk/device_requirements.h), and images and buffers with their own
// memory.
#pragma once

#include "engine/vk/context.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

struct HostVulkan {
  // With `validation`, the host's own messenger prints each message to stderr and, when
  // `message_count` is given, counts it there; it lives until after the device is destroyed, so
  // objects a library left alive on the device are reported and counted too.
  explicit HostVulkan(bool validation, std::atomic<uint32_t>* message_count = nullptr);
  ~HostVulkan();
  HostVulkan(const HostVulkan&) = delete;
  HostVulkan& operator=(const HostVulkan&) = delete;

  // What the library's context adopts (it owns none of it).
  engine::vk::HostDevice host_device() const;

  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  bool validation = false;
  std::vector<std::string> device_extensions;
  engine::vk::DeviceFeatures enabled;  // the chain the device was created with
};

// A 2D image with its own device-local memory, destroyed with the host.
struct HostImage {
  HostImage(VkPhysicalDevice physical_device, VkDevice device, uint32_t width, uint32_t height, VkFormat format,
            VkImageUsageFlags usage);
  ~HostImage();
  HostImage(const HostImage&) = delete;
  HostImage& operator=(const HostImage&) = delete;

  VkDevice device = VK_NULL_HANDLE;
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
};

// A buffer in host-visible, coherent memory, filled once from `bytes` (the host's geometry).
struct HostBuffer {
  HostBuffer(VkPhysicalDevice physical_device, VkDevice device, const void* bytes, VkDeviceSize size,
             VkBufferUsageFlags usage);
  ~HostBuffer();
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;

  VkDevice device = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};

// Throws std::runtime_error naming the call when a Vulkan call fails.
void host_check(VkResult result, const char* call);
