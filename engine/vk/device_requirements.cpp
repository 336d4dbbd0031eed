#include "engine/vk/device_requirements.h"

#include <algorithm>
#include <cstring>

namespace engine::vk {
namespace {

// The required features as accessors into a DeviceFeatures, so that enabling, checking and naming
// come from one table.
using Access = VkBool32& (*)(DeviceFeatures&);
struct Required {
  const char* name;
  Access field;
};

const Required k_required[] = {
    {"largePoints", [](DeviceFeatures& f) -> VkBool32& { return f.core.features.largePoints; }},
    {"hostQueryReset", [](DeviceFeatures& f) -> VkBool32& { return f.v12.hostQueryReset; }},
    {"dynamicRendering", [](DeviceFeatures& f) -> VkBool32& { return f.v13.dynamicRendering; }},
    {"synchronization2", [](DeviceFeatures& f) -> VkBool32& { return f.v13.synchronization2; }},
};

// Used where the device has them; each picks a way of rendering the 3D grids (liquid/solver/grid_layout.h):
// geometry shaders route full-screen passes to a slice, shaderOutputLayer lets a vertex shader do it.
// Without either, 3D grids are stored as 2D atlases of their slices; 2D scenes need neither.
// dualSrcBlend: a composited liquid filters the host's colour behind it per channel (its
// absorption tints what shows through); without it, by one grey transmittance.
const Required k_optional[] = {
    {"geometryShader", [](DeviceFeatures& f) -> VkBool32& { return f.core.features.geometryShader; }},
    {"shaderOutputLayer", [](DeviceFeatures& f) -> VkBool32& { return f.v12.shaderOutputLayer; }},
    {"dualSrcBlend", [](DeviceFeatures& f) -> VkBool32& { return f.core.features.dualSrcBlend; }},
};

VkBool32 value(const DeviceFeatures& features, Access field) { return field(const_cast<DeviceFeatures&>(features)); }

}  // namespace

std::vector<const char*> required_device_extensions() { return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME}; }

DeviceFeatures::DeviceFeatures() {
  core.pNext = &v11;
  v11.pNext = &v12;
  v12.pNext = &v13;
  v13.pNext = nullptr;
}

void DeviceFeatures::query(VkPhysicalDevice device) { vkGetPhysicalDeviceFeatures2(device, chain()); }

void DeviceFeatures::read_chain(const void* pnext) {
  for (auto* s = static_cast<const VkBaseInStructure*>(pnext); s; s = s->pNext) {
    switch (s->sType) {
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2:
        core.features = reinterpret_cast<const VkPhysicalDeviceFeatures2*>(s)->features;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES: {
        const auto* f = reinterpret_cast<const VkPhysicalDeviceVulkan12Features*>(s);
        v12.hostQueryReset = f->hostQueryReset;
        v12.shaderOutputLayer = f->shaderOutputLayer;
        break;
      }
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: {
        const auto* f = reinterpret_cast<const VkPhysicalDeviceVulkan13Features*>(s);
        v13.dynamicRendering = f->dynamicRendering;
        v13.synchronization2 = f->synchronization2;
        break;
      }
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES:
        v12.hostQueryReset = reinterpret_cast<const VkPhysicalDeviceHostQueryResetFeatures*>(s)->hostQueryReset;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES:
        v13.dynamicRendering = reinterpret_cast<const VkPhysicalDeviceDynamicRenderingFeatures*>(s)->dynamicRendering;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES:
        v13.synchronization2 = reinterpret_cast<const VkPhysicalDeviceSynchronization2Features*>(s)->synchronization2;
        break;
      default:
        break;
    }
  }
}

void enable_required(DeviceFeatures& features, const DeviceFeatures& supported) {
  for (const Required& r : k_required) r.field(features) = VK_TRUE;
  for (const Required& r : k_optional)
    if (value(supported, r.field)) r.field(features) = VK_TRUE;
}

std::vector<std::string> missing_requirements(const DeviceFeatures& enabled, const std::vector<std::string>& extensions,
                                              uint32_t api_version) {
  std::vector<std::string> missing;
  if (api_version < k_required_api_version) missing.push_back("Vulkan 1.3");
  for (const char* extension : required_device_extensions())
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) missing.push_back(extension);
  for (const Required& r : k_required)
    if (!value(enabled, r.field)) missing.push_back(r.name);
  return missing;
}

}  // namespace engine::vk
