#include "tests/support/gpu.h"
#include "tools/keep_modules_loaded.h"  // sanitizer builds: the driver stays mapped for LeakSanitizer

#include <memory>
#include <string>

namespace test {
namespace {

std::unique_ptr<engine::vk::Context> g_context;
std::string g_failure;

}  // namespace

engine::vk::Context& gpu() {
  if (!g_context) {
    if (!g_failure.empty()) FAIL("no Vulkan device for GPU tests: " << g_failure);
    try {
      g_context = std::make_unique<engine::vk::Context>(engine::vk::ContextOptions{.validation = true});
    } catch (const std::exception& error) {
      g_failure = error.what();
      FAIL("no Vulkan device for GPU tests: " << g_failure);
    }
  }
  return *g_context;
}

uint32_t total_validation_messages() { return g_context ? g_context->validation_message_count() : 0; }

}  // namespace test
