#include "engine/vk/sampler.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

namespace engine::vk {

Sampler::Sampler(Context& context, VkFilter filter) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  const VkDevice device = context.device();
  VkSampler sampler = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  sampler_ = {device, sampler, vkDestroySampler};
}

}  // namespace engine::vk
