// RAII sampler: nearest for texelFetch-style reads, linear for filtered rendering lookups. Both
// clamp to the edge, so a lookup past the grid reads the boundary cell.
#pragma once

#include "engine/vk/handle.h"

#include <vulkan/vulkan.h>

namespace engine::vk {

class Context;

class Sampler {
 public:
  Sampler() = default;
  Sampler(Context& context, VkFilter filter);

  VkSampler handle() const { return sampler_.get(); }

 private:
  UniqueHandle<VkSampler> sampler_;
};

}  // namespace engine::vk
