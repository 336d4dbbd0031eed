// RAII sampler: nearest for texelFetch-style reads, linear for filtered rendering lookups. Both
// clamp to the edge, so a lookup past the grid reads the boundary cell.
#pragma once

#include <vulkan/vulkan.h>

namespace engine::vk {

class Context;

class Sampler {
 public:
  Sampler() = default;
  Sampler(Context& context, VkFilter filter);
  ~Sampler();
  Sampler(Sampler&& other) noexcept;
  Sampler& operator=(Sampler&& other) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;

  VkSampler handle() const { return sampler_; }

 private:
  void release();
  Context* context_ = nullptr;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace engine::vk
