#include "host_vulkan.h"

#include "engine/vk/device_requirements.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL host_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                            VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  std::fprintf(stderr, "host validation: %s\n", data->pMessage);
  if (user) static_cast<std::atomic<uint32_t>*>(user)->fetch_add(1);
  return VK_FALSE;
}

}  // namespace

void host_check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(call) + " failed (VkResult " + std::to_string(result) + ")");
}

HostVulkan::HostVulkan(bool with_validation, std::atomic<uint32_t>* message_count) : validation(with_validation) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "liquid_host";
  app.apiVersion = engine::vk::k_required_api_version;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* debug_utils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation) {
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &debug_utils;
  }
  host_check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance");
  if (validation) {
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    messenger_info.pfnUserCallback = host_message;
    messenger_info.pUserData = message_count;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    host_check(create ? create(instance, &messenger_info, nullptr, &messenger) : VK_ERROR_EXTENSION_NOT_PRESENT,
               "vkCreateDebugUtilsMessengerEXT");
  }

  // The first device with Vulkan 1.3, what the library needs, and a graphics queue.
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::string reasons;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(candidate, &props);
    engine::vk::DeviceFeatures supported;
    supported.query(candidate);
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(candidate, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> available(n);
    vkEnumerateDeviceExtensionProperties(candidate, nullptr, &n, available.data());
    std::vector<std::string> names;
    for (const auto& e : available) names.push_back(e.extensionName);
    const auto missing = engine::vk::missing_requirements(supported, names, props.apiVersion);
    if (!missing.empty()) {
      reasons += std::string(props.deviceName) + " lacks " + missing.front() + "; ";
      continue;
    }
    physical_device = candidate;
    engine::vk::enable_required(enabled, supported);
    break;
  }
  if (!physical_device) throw std::runtime_error("no Vulkan device can run the liquid: " + reasons);

  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, families.data());
  queue_family = uint32_t(std::find_if(families.begin(), families.end(),
                                       [](const auto& f) { return (f.queueFlags & VK_QUEUE_GRAPHICS_BIT) != 0; }) -
                          families.begin());
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  std::vector<const char*> extensions = engine::vk::required_device_extensions();
  for (const char* e : extensions) device_extensions.push_back(e);
  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, enabled.chain()};
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = uint32_t(extensions.size());
  device_info.ppEnabledExtensionNames = extensions.data();
  host_check(vkCreateDevice(physical_device, &device_info, nullptr, &device), "vkCreateDevice");
  vkGetDeviceQueue(device, queue_family, 0, &queue);
}

HostVulkan::~HostVulkan() {
  if (device) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

engine::vk::HostDevice HostVulkan::host_device() const {
  engine::vk::HostDevice host;
  host.instance = instance;
  host.physical_device = physical_device;
  host.device = device;
  host.queue_family = queue_family;
  host.queue_index = 0;
  host.api_version = engine::vk::k_required_api_version;
  host.enabled_device_extensions = device_extensions;
  host.enabled_features = &enabled.core;
  host.debug_utils = validation;
  return host;
}

namespace {

// The first memory type `requirements` allow that has every one of `properties`.
uint32_t memory_type(VkPhysicalDevice physical_device, const VkMemoryRequirements& requirements,
                     VkMemoryPropertyFlags properties) {
  VkPhysicalDeviceMemoryProperties memory_properties{};
  vkGetPhysicalDeviceMemoryProperties(physical_device, &memory_properties);
  for (uint32_t type = 0; type < memory_properties.memoryTypeCount; ++type)
    if ((requirements.memoryTypeBits & (1u << type)) &&
        (memory_properties.memoryTypes[type].propertyFlags & properties) == properties)
      return type;
  throw std::runtime_error("no memory type for a host resource");
}

// Memory for `requirements` of the first type that has every one of `properties`.
VkDeviceMemory allocate_memory(VkPhysicalDevice physical_device, VkDevice device, const VkMemoryRequirements& requirements,
                               VkMemoryPropertyFlags properties) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = memory_type(physical_device, requirements, properties);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  host_check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

}  // namespace

HostImage::HostImage(VkPhysicalDevice physical_device, VkDevice device_, uint32_t width, uint32_t height,
                     VkFormat format, VkImageUsageFlags usage)
    : device(device_) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  host_check(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage");
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device, image, &requirements);
  memory = allocate_memory(physical_device, device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  host_check(vkBindImageMemory(device, image, memory, 0), "vkBindImageMemory");
}

HostImage::~HostImage() {
  if (image) vkDestroyImage(device, image, nullptr);
  if (memory) vkFreeMemory(device, memory, nullptr);
}

HostBuffer::HostBuffer(VkPhysicalDevice physical_device, VkDevice device_, const void* bytes, VkDeviceSize size_,
                       VkBufferUsageFlags usage)
    : device(device_), size(size_) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  host_check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  memory = allocate_memory(physical_device, device, requirements,
                           VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  host_check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  host_check(vkMapMemory(device, memory, 0, size, 0, &mapped), "vkMapMemory");
  std::memcpy(mapped, bytes, size_t(size));
  vkUnmapMemory(device, memory);
}

HostBuffer::~HostBuffer() {
  if (buffer) vkDestroyBuffer(device, buffer, nullptr);
  if (memory) vkFreeMemory(device, memory, nullptr);
}
