#include "engine/vk/sampler.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

#include <utility>

namespace engine::vk {

Sampler::Sampler(Context& context, VkFilter filter) : context_(&context) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler_));
}

Sampler::~Sampler() { release(); }

Sampler::Sampler(Sampler&& other) noexcept { *this = std::move(other); }

Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
  }
  return *this;
}

void Sampler::release() {
  if (context_ && sampler_) vkDestroySampler(context_->device(), sampler_, nullptr);
  sampler_ = VK_NULL_HANDLE;
  context_ = nullptr;
}

}  // namespace engine::vk
