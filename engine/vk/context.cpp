#include "engine/vk/context.h"

#include "engine/vk/vk_check.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <optional>
#include <vector>

namespace engine::vk {
namespace {

constexpr const char* k_validation_layer = "VK_LAYER_KHRONOS_validation";
std::mutex g_message_mutex;

VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
    static_cast<Context*>(user)->on_validation_message(data->pMessage);
  return VK_FALSE;
}

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

std::vector<std::string> device_extensions(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> properties(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, properties.data());
  std::vector<std::string> names;
  for (const auto& e : properties) names.push_back(e.extensionName);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// The first queue family with graphics that the host's filter (if any) accepts.
std::optional<uint32_t> graphics_family(VkInstance instance, VkPhysicalDevice device, const ContextOptions& options) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i)
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
        (!options.queue_family_filter || options.queue_family_filter(instance, device, i)))
      return i;
  return std::nullopt;
}

// Lower is better: the automatic choice prefers a real GPU and falls back to lavapipe.
int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

// Why a device cannot run us, or "" when it can.
std::string unsuitability(VkInstance instance, VkPhysicalDevice device, const ContextOptions& options) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device, &props);
  DeviceFeatures supported;
  supported.query(device);
  const std::vector<std::string> extensions = device_extensions(device);
  std::vector<std::string> missing = missing_requirements(supported, extensions, props.apiVersion);
  for (const char* extension : options.device_extensions)
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) missing.push_back(extension);
  if (!missing.empty()) return "not supported: " + joined(missing);
  if (!graphics_family(instance, device, options)) return "no graphics queue family the host accepts";
  return "";
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

Context::Context(const ContextOptions& options) : print_messages_(options.print_validation_messages) {
  std::string preference = options.device;
  // RASTERLIQUIDS_DEVICE, or LIQUID_DEVICE, its name before the engine had one of its own.
  if (preference.empty())
    for (const char* variable : {"RASTERLIQUIDS_DEVICE", "LIQUID_DEVICE"})
      if (const char* env = std::getenv(variable); env && preference.empty()) preference = env;
  try {
    create_instance(options);
    pick_physical_device(preference, options);
    create_device(options);
    finish_setup();
  } catch (...) {
    release();
    throw;
  }
}

Context::Context(const HostDevice& host, const ContextOptions& options)
    : instance_(host.instance),
      physical_device_(host.physical_device),
      device_(host.device),
      queue_family_(host.queue_family),
      print_messages_(options.print_validation_messages),
      owns_device_(false) {
  // Only print_validation_messages applies to a host's device: the rest choose or create what the
  // host has already made. Given anyway, they would be silently ignored, so they are refused.
  const char* ignored = options.validation                    ? "validation"
                        : !options.device.empty()             ? "device"
                        : !options.instance_extensions.empty() ? "instance_extensions"
                        : !options.device_extensions.empty()  ? "device_extensions"
                        : options.enable_features             ? "enable_features"
                        : options.queue_family_filter         ? "queue_family_filter"
                                                              : nullptr;
  if (ignored)
    throw std::invalid_argument(std::string("engine: ContextOptions::") + ignored +
                                " does not apply to a host's device (the host creates the instance and device; "
                                "HostDevice::debug_utils adds the library's message counter)");
  try {
    if (!instance_ || !physical_device_ || !device_)
      throw NoDeviceError("the host device is incomplete (instance, physical device and device are required)");
    read_device_properties();
    DeviceFeatures enabled;
    enabled.read_chain(host.enabled_features);
    const std::vector<std::string> missing =
        missing_requirements(enabled, host.enabled_device_extensions, std::min(host.api_version, properties_.apiVersion));
    if (!missing.empty())
      throw NoDeviceError("the host's Vulkan device lacks what the library needs: " + joined(missing));
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, families.data());
    if (queue_family_ >= count || !(families[queue_family_].queueFlags & VK_QUEUE_GRAPHICS_BIT))
      throw NoDeviceError("the host's queue family " + std::to_string(queue_family_) + " has no graphics");
    if (host.queue_index >= families[queue_family_].queueCount)
      throw NoDeviceError("the host's queue index " + std::to_string(host.queue_index) + " does not exist");
    vertex_layer_output_ = enabled.v12.shaderOutputLayer == VK_TRUE;
    geometry_shader_ = enabled.core.features.geometryShader == VK_TRUE;
    dual_source_blend_ = enabled.core.features.dualSrcBlend == VK_TRUE;
    vkGetDeviceQueue(device_, queue_family_, host.queue_index, &queue_);
    if (host.debug_utils) create_messenger();
    finish_setup();
  } catch (...) {
    release();
    throw;
  }
}

Context::~Context() { release(); }

void Context::release() {
  if (device_) {
    // A host's device may still run the host's own work: wait for our queue only.
    if (owns_device_) vkDeviceWaitIdle(device_);
    else if (queue_) vkQueueWaitIdle(queue_);
    for (const RecycledCommands& r : recycled_commands_) vkDestroyFence(device_, r.fence, nullptr);
    recycled_commands_.clear();  // their command buffers go with the pool
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    if (owns_device_) vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    if (owns_device_) vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

void Context::create_instance(const ContextOptions& options) {
  uint32_t loader_version = 0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS || loader_version < VK_API_VERSION_1_3)
    throw NoDeviceError("the Vulkan loader does not support Vulkan 1.3");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "rasterization-liquids";
  app.pEngineName = "rasterization-liquids";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  // Synchronization validation is enabled through VkValidationFeaturesEXT: Debian 12's layer
  // predates VK_EXT_layer_settings.
  VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = debug_callback;
  messenger_info.pUserData = this;

  extensions.insert(extensions.end(), options.instance_extensions.begin(), options.instance_extensions.end());
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (options.validation) {
    if (!has_layer(k_validation_layer))
      throw std::runtime_error(
          "validation was requested but VK_LAYER_KHRONOS_validation is not installed "
          "(Debian package vulkan-validationlayers)");
    layers.push_back(k_validation_layer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    features.pNext = &messenger_info;
    info.pNext = &features;
  }
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
    throw NoDeviceError(std::string("no Vulkan driver could be loaded (vkCreateInstance: ") +
                        result_name(result) + ")");
  VK_CHECK(result);

  if (options.validation) create_messenger();
}

void Context::create_messenger() {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = debug_callback;
  info.pUserData = this;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) throw std::runtime_error("VK_EXT_debug_utils is not enabled on the instance");
  VK_CHECK(create(instance_, &info, nullptr, &messenger_));
  set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
      vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
}

void Context::pick_physical_device(const std::string& preference, const ContextOptions& options) {
  uint32_t count = 0;
  const VkResult result = vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  if (result != VK_SUCCESS || count == 0) throw NoDeviceError("no Vulkan device found");
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));

  std::string reasons;
  std::vector<std::pair<int, VkPhysicalDevice>> candidates;
  for (uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(devices[i], &props);
    const std::string why = unsuitability(instance_, devices[i], options);
    if (!why.empty()) {
      reasons += std::string(reasons.empty() ? "" : "; ") + props.deviceName + ": " + why;
      continue;
    }
    const std::string pref = lower(preference);
    bool match = true;
    if (pref == "discrete") match = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
    else if (pref == "integrated") match = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
    else if (pref == "cpu") match = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    else if (!pref.empty() && std::all_of(pref.begin(), pref.end(), ::isdigit)) match = std::to_string(i) == pref;
    else if (!pref.empty()) match = lower(props.deviceName).find(pref) != std::string::npos;
    if (match) candidates.push_back({type_rank(props.deviceType), devices[i]});
  }
  if (candidates.empty()) {
    std::string message = preference.empty() ? "no suitable Vulkan device"
                                             : "no suitable Vulkan device matches '" + preference + "'";
    if (!reasons.empty()) message += " (" + reasons + ")";
    throw NoDeviceError(message);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  physical_device_ = candidates.front().second;
  read_device_properties();
}

void Context::read_device_properties() {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physical_device_, &props2);
  properties_ = props2.properties;
  driver_description_ = std::string(driver.driverName) + " " + driver.driverInfo;
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
}

void Context::create_device(const ContextOptions& options) {
  queue_family_ = *graphics_family(instance_, physical_device_, options);
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  DeviceFeatures supported, enabled;
  supported.query(physical_device_);
  enable_required(enabled, supported);
  if (options.enable_features) options.enable_features(enabled, supported);
  vertex_layer_output_ = enabled.v12.shaderOutputLayer == VK_TRUE;
  geometry_shader_ = enabled.core.features.geometryShader == VK_TRUE;
  dual_source_blend_ = enabled.core.features.dualSrcBlend == VK_TRUE;

  std::vector<const char*> extensions = required_device_extensions();
  extensions.insert(extensions.end(), options.device_extensions.begin(), options.device_extensions.end());
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, enabled.chain()};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_device_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

void Context::finish_setup() {
  cmd_push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_));
}

Context::RecycledCommands Context::take_recycled_commands() {
  std::lock_guard<std::mutex> lock(recycled_mutex_);
  if (recycled_commands_.empty()) return {};
  const RecycledCommands commands = recycled_commands_.back();
  recycled_commands_.pop_back();
  return commands;
}

void Context::recycle_commands(RecycledCommands commands) {
  std::lock_guard<std::mutex> lock(recycled_mutex_);
  recycled_commands_.push_back(commands);
}

void Context::on_validation_message(const char* message) {
  ++validation_messages_;
  std::lock_guard lock(g_message_mutex);
  last_message_ = message;
  if (print_messages_) std::fprintf(stderr, "[validation] %s\n", message);
}

std::string Context::last_validation_message() const {
  std::lock_guard lock(g_message_mutex);
  return last_message_;
}

uint32_t Context::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (memory_properties_.memoryTypes[i].propertyFlags & flags) == flags)
      return i;
  throw std::runtime_error("no Vulkan memory type with the requested properties");
}

bool Context::format_supports(VkFormat format, VkFormatFeatureFlags features) const {
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(physical_device_, format, &props);
  return (props.optimalTilingFeatures & features) == features;
}

void Context::set_name(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!set_object_name_ || name.empty()) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  set_object_name_(device_, &info);
}

}  // namespace engine::vk
