// What the library needs of a Vulkan device, in one place: the version, the device extensions and
// the features. The context enables exactly these when it creates its own device; a host that
// creates the device itself enables them too (enable_required()) and the context checks them when
// it adopts the device (missing_requirements() names whatever is absent).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace engine::vk {

constexpr uint32_t k_required_api_version = VK_API_VERSION_1_3;

// Device extensions the library calls (push descriptors: one descriptor set written at draw time).
std::vector<const char*> required_device_extensions();

// A VkPhysicalDeviceFeatures2 chain with the Vulkan 1.1, 1.2 and 1.3 feature structs. Not copyable
// (the chain points into itself); build one, fill it, pass chain() as VkDeviceCreateInfo::pNext.
struct DeviceFeatures {
  DeviceFeatures();
  DeviceFeatures(const DeviceFeatures&) = delete;
  DeviceFeatures& operator=(const DeviceFeatures&) = delete;

  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};

  VkPhysicalDeviceFeatures2* chain() { return &core; }
  // What `device` supports.
  void query(VkPhysicalDevice device);
  // Reads the features a host enabled from its VkDeviceCreateInfo::pNext chain (the 1.1/1.2/1.3
  // structs or the individual ones the library needs; anything else in the chain is skipped).
  void read_chain(const void* device_create_pnext);
};

// Sets every feature the library needs in `features` (leaving the others as they are).
// The optional features (geometry shaders, gl_Layer from vertex shaders: ways of rendering into the
// slices of 3D images; dual-source blending: a composited liquid's per-channel transmittance) are
// set only where `supported` has them.
void enable_required(DeviceFeatures& features, const DeviceFeatures& supported);

// The required features and extensions absent from what was enabled, by name ("geometryShader",
// "VK_KHR_push_descriptor", ...); empty when everything is there.
std::vector<std::string> missing_requirements(const DeviceFeatures& enabled, const std::vector<std::string>& extensions,
                                              uint32_t api_version);

}  // namespace engine::vk
