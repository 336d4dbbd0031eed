// Graphics pipelines built from embedded SPIR-V, for dynamic rendering (no VkRenderPass). Resources
// are bound with push descriptors: one set, written at draw time, so passes need no descriptor
// pools and a pass can bind a different ping-pong image every step.
#pragma once

#include "engine/vk/handle.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace engine::vk {

class Context;

enum class BlendMode {
  None,      // overwrite
  Additive,  // dst + src on every channel (the splat's accumulation)
  Alpha,     // src.a * src + (1 - src.a) * dst
  Min,       // min(dst, src) on every channel (a distance kept where it is the smallest)
  // Dual-source (the device's dualSrcBlend): src + src1 * dst per colour channel, so a translucent
  // surface filters what lies behind it channel by channel; alpha as Alpha's.
  Transmit,
};

enum class DescriptorKind { SampledImage, UniformBuffer };

struct DescriptorBinding {
  uint32_t binding = 0;
  DescriptorKind kind = DescriptorKind::SampledImage;
  VkShaderStageFlags stages = VK_SHADER_STAGE_ALL_GRAPHICS;
};

struct GraphicsPipelineDesc {
  std::string name;
  std::span<const uint32_t> vertex;
  std::span<const uint32_t> geometry;  // empty = none
  std::span<const uint32_t> fragment;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  std::vector<VkFormat> color_formats;
  std::vector<BlendMode> blend;  // one per colour format; missing entries are None
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  bool depth_test = false;
  bool depth_write = false;
  // Which fragment passes the depth test: LESS_OR_EQUAL for depth 0 at the near plane, the host's
  // GREATER_OR_EQUAL for reversed Z (1 at the near plane).
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
  std::vector<DescriptorBinding> bindings;
  uint32_t push_constant_size = 0;  // bytes, at most 128 (lavapipe's limit)
  // Specialization constants for every stage: entry i sets constant_id i (32-bit int or bool).
  // A stage that declares no such id ignores it.
  std::vector<int32_t> specialization;
};

class GraphicsPipeline {
 public:
  GraphicsPipeline() = default;
  GraphicsPipeline(Context& context, const GraphicsPipelineDesc& desc);

  VkPipeline handle() const { return objects_->pipeline.get(); }
  VkPipelineLayout layout() const { return objects_->layout.get(); }
  const std::string& name() const { return name_; }
  // The descriptor bindings of its layout, as declared (engine::passes::PassBindings checks against them).
  const std::vector<DescriptorBinding>& bindings() const { return bindings_; }

  // Binds the pipeline and sets a full viewport and scissor of the given size.
  void bind(VkCommandBuffer cmd, uint32_t width, uint32_t height) const;
  // Push-descriptor writes for the next draw.
  void push_image(VkCommandBuffer cmd, uint32_t binding, VkImageView view, VkSampler sampler) const;
  void push_uniform(VkCommandBuffer cmd, uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                    VkDeviceSize size) const;
  void push_constants(VkCommandBuffer cmd, const void* data, uint32_t size) const;
  template <class T>
  void push_constants(VkCommandBuffer cmd, const T& value) const {
    push_constants(cmd, &value, sizeof(T));
  }

 private:
  struct Objects {
    UniqueHandle<VkDescriptorSetLayout> set_layout;
    UniqueHandle<VkPipelineLayout> layout;  // uses set_layout
    UniqueHandle<VkPipeline> pipeline;      // uses layout
  };

  ResetOnMove<Context*> context_;
  HandleGroup<Objects> objects_;
  uint32_t push_constant_size_ = 0;
  std::string name_;
  std::vector<DescriptorBinding> bindings_;
};

}  // namespace engine::vk
