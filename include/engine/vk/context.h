// The Vulkan context the library runs on: instance, one physical device, one graphics queue, a
// command pool, and (when asked) the validation layer with synchronization validation and a message
// counter. It either creates all of that itself or adopts a host engine's own instance, device and
// queue without owning them.
#pragma once

#include "engine/vk/device_memory.h"
#include "engine/vk/device_requirements.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

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
  // variable RASTERLIQUIDS_DEVICE (or its older name LIQUID_DEVICE) overrides an empty value.
  std::string device;
  // Print validation messages to stderr as they come (they are counted either way).
  bool print_validation_messages = true;

  // When the context creates the device: more instance and device extensions (for a window:
  // VK_KHR_surface + the platform's surface extension, and VK_KHR_swapchain), more features on top
  // of the library's (`enable` is what will be enabled, `supported` what the device has), and a
  // test for the queue family (e.g. that it can present to the host's surface).
  std::vector<const char*> instance_extensions;
  std::vector<const char*> device_extensions;
  std::function<void(DeviceFeatures& enable, const DeviceFeatures& supported)> enable_features;
  std::function<bool(VkInstance, VkPhysicalDevice, uint32_t queue_family)> queue_family_filter;
};

// A host engine's own device, for Context(const HostDevice&): nothing here is destroyed by the
// library. The host creates its device with k_required_api_version, required_device_extensions()
// and enable_required() (device_requirements.h) and passes what it enabled, so that a missing
// requirement is reported by name instead of failing later.
struct HostDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;  // must support graphics
  uint32_t queue_index = 0;
  uint32_t api_version = VK_API_VERSION_1_3;   // VkApplicationInfo::apiVersion the host asked for
  std::vector<std::string> enabled_device_extensions;
  const void* enabled_features = nullptr;      // the VkDeviceCreateInfo::pNext chain it used
  // The instance was created with VK_EXT_debug_utils (and, for tests, the validation layer): the
  // context then adds a messenger that counts validation messages.
  bool debug_utils = false;
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  // Adopts a host's device. Throws NoDeviceError naming every requirement the device lacks. Of the
  // options only print_validation_messages applies (any other set is refused with
  // std::invalid_argument naming it); HostDevice::debug_utils adds the library's own messenger,
  // beside any of the host's, which counts messages (validation_message_count()) and prints them
  // unless print_validation_messages is false.
  explicit Context(const HostDevice& host, const ContextOptions& options = {});
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
  // False when the device is a host's (adopted): the host destroys it.
  bool owns_device() const { return owns_device_; }
  // Whether vertex shaders may write gl_Layer (Vulkan 1.2 shaderOutputLayer).
  bool supports_vertex_layer_output() const { return vertex_layer_output_; }
  // Whether geometry shaders were enabled (geometryShader).
  bool supports_geometry_shader() const { return geometry_shader_; }
  // dualSrcBlend enabled: BlendMode::Transmit can be used.
  bool supports_dual_source_blend() const { return dual_source_blend_; }

  // Number of validation warnings and errors reported since creation (or the last reset).
  uint32_t validation_message_count() const { return validation_messages_.load(); }
  void reset_validation_message_count() { validation_messages_ = 0; }
  // The last validation message, for test failure output.
  std::string last_validation_message() const;

  // Device memory the engine's buffers and images hold now, and the most they held at once since
  // the last reset_memory_peak() (bytes; a host's own adopted images are not counted).
  VkDeviceSize memory_in_use() const { return memory_.in_use(); }
  VkDeviceSize memory_peak() const { return memory_.peak(); }
  void reset_memory_peak() { memory_.reset_peak(); }
  MemoryCounter& memory_counter() { return memory_; }

  // Memory type index with the given property flags among the allowed bits; throws if none.
  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags flags) const;
  // Whether `format` supports every feature bit in `features` for optimal tiling.
  bool format_supports(VkFormat format, VkFormatFeatureFlags features) const;

  // Sets a debug name that validation messages and capture tools show (no-op without the layer).
  void set_name(VkObjectType type, uint64_t handle, const std::string& name) const;

  // A command buffer of command_pool() and its fence, handed back by an engine::vk::CommandBuffer
  // for the next one to reuse. Recycled because lavapipe (Mesa 22.3) keeps about 3 KB for every
  // command buffer ever allocated until the device is destroyed, freed or not: a host reading
  // state back every frame through fresh command buffers grew without bound (docs/memory.md).
  struct RecycledCommands {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
  };
  // One from the recycle list, or an empty pair when it has none.
  RecycledCommands take_recycled_commands();
  // `commands` must not be pending on the queue.
  void recycle_commands(RecycledCommands commands);

  PFN_vkCmdPushDescriptorSetKHR cmd_push_descriptor_set = nullptr;

  // Called by the debug callback.
  void on_validation_message(const char* message);

 private:
  void create_instance(const ContextOptions& options);
  void create_messenger();
  void pick_physical_device(const std::string& preference, const ContextOptions& options);
  void read_device_properties();
  void create_device(const ContextOptions& options);
  void finish_setup();
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
  bool owns_device_ = true;
  bool vertex_layer_output_ = false;
  bool geometry_shader_ = false;
  bool dual_source_blend_ = false;
  std::atomic<uint32_t> validation_messages_{0};
  MemoryCounter memory_;
  mutable std::string last_message_;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
  std::mutex recycled_mutex_;
  std::vector<RecycledCommands> recycled_commands_;
};

}  // namespace engine::vk
