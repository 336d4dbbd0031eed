// The headless Vulkan context: instance, one physical device, one graphics queue, a command pool,
// and (when asked) the validation layer with synchronization validation and a message counter.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace engine::vk {

// No usable Vulkan device (no driver, or none with Vulkan 1.3 and what we need). Tools print it as
// one line and exit non-zero; GPU tests report it instead of crashing.
class NoDeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ContextOptions {
  // Validation layer + synchronization validation + debug messenger. Always on in tests.
  bool validation = false;
  // "" = automatic (discrete, then integrated, then virtual, then CPU); "discrete", "integrated",
  // "cpu", a device index ("0", "1", ...) or a substring of the device name. The environment
  // variable LIQUID_DEVICE overrides an empty value.
  std::string device;
  // Print validation messages to stderr as they come (they are counted either way).
  bool print_validation_messages = true;
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  VkCommandPool command_pool() const { return command_pool_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  std::string device_name() const { return properties_.deviceName; }
  // "Mesa 22.3.6" style driver description from VkPhysicalDeviceDriverProperties.
  std::string driver_description() const { return driver_description_; }
  bool is_cpu_device() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }
  // Whether vertex shaders may write gl_Layer (Vulkan 1.2 shaderOutputLayer).
  bool supports_vertex_layer_output() const { return vertex_layer_output_; }

  // Number of validation warnings and errors reported since creation (or the last reset).
  uint32_t validation_message_count() const { return validation_messages_.load(); }
  void reset_validation_message_count() { validation_messages_ = 0; }
  // The last validation message, for test failure output.
  std::string last_validation_message() const;

  // Memory type index with the given property flags among the allowed bits; throws if none.
  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags flags) const;
  // Whether `format` supports every feature bit in `features` for optimal tiling.
  bool format_supports(VkFormat format, VkFormatFeatureFlags features) const;

  // Sets a debug name that validation messages and capture tools show (no-op without the layer).
  void set_name(VkObjectType type, uint64_t handle, const std::string& name) const;

  PFN_vkCmdPushDescriptorSetKHR cmd_push_descriptor_set = nullptr;

  // Called by the debug callback.
  void on_validation_message(const char* message);

 private:
  void create_instance(const ContextOptions& options);
  void pick_physical_device(const std::string& preference);
  void create_device();
  void release();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  std::string driver_description_;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  bool print_messages_ = true;
  bool vertex_layer_output_ = false;
  std::atomic<uint32_t> validation_messages_{0};
  mutable std::string last_message_;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
};

}  // namespace engine::vk
