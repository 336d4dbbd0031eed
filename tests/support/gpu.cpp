#include "tests/support/gpu.h"
#include "tools/common/keep_modules_loaded.h"  // sanitizer builds: the driver stays mapped for LeakSanitizer

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace test {
namespace {

std::unique_ptr<engine::vk::Context> g_context;
std::string g_failure;
std::map<LayerFeatures, std::unique_ptr<engine::vk::Context>> g_masked;

engine::vk::Context& create(std::unique_ptr<engine::vk::Context>& slot, const engine::vk::ContextOptions& options) {
  if (!slot) {
    if (!g_failure.empty()) FAIL("no Vulkan device for GPU tests: " << g_failure);
    try {
      slot = std::make_unique<engine::vk::Context>(options);
    } catch (const std::exception& error) {
      g_failure = error.what();
      FAIL("no Vulkan device for GPU tests: " << g_failure);
    }
  }
  return *slot;
}

}  // namespace

engine::vk::Context& gpu() { return create(g_context, engine::vk::ContextOptions{.validation = true}); }

engine::vk::Context& gpu_with(LayerFeatures features) {
  engine::vk::ContextOptions options{.validation = true};
  // Runs after the library's own enable_required(), which turned on whatever the device supports.
  options.enable_features = [features](engine::vk::DeviceFeatures& enable, const engine::vk::DeviceFeatures&) {
    if (!features.geometry_shader) enable.core.features.geometryShader = VK_FALSE;
    if (!features.vertex_layer_output) enable.v12.shaderOutputLayer = VK_FALSE;
  };
  return create(g_masked[features], options);
}

uint32_t total_validation_messages() {
  uint32_t total = g_context ? g_context->validation_message_count() : 0;
  for (const auto& [features, context] : g_masked)
    if (context) total += context->validation_message_count();
  return total;
}

void release_contexts() {
  g_masked.clear();
  g_context.reset();
}

}  // namespace test
