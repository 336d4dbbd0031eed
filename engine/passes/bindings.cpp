#include "engine/passes/bindings.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace engine::passes {

const vk::DescriptorBinding& PassBindings::layout_entry(uint32_t binding, vk::DescriptorKind kind) const {
  const auto& table = pipeline_->bindings();
  const auto it = std::find_if(table.begin(), table.end(), [&](const auto& b) { return b.binding == binding; });
  if (it == table.end() || it->kind != kind)
    throw std::logic_error(pipeline_->name() + ": binding " + std::to_string(binding) + " is not a " +
                           (kind == vk::DescriptorKind::SampledImage ? "sampled image" : "uniform block") +
                           " of the pipeline's layout");
  if (std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.binding == binding; }))
    throw std::logic_error(pipeline_->name() + ": binding " + std::to_string(binding) + " is bound twice");
  return *it;
}

void PassBindings::bind_image(graph::PassBuilder& builder, uint32_t binding, graph::ImageHandle image,
                              VkSampler sampler) {
  const VkShaderStageFlags stages = layout_entry(binding, vk::DescriptorKind::SampledImage).stages;
  // One graph read per stage that samples it (a second read of an image in a pass adds stages).
  if (stages & VK_SHADER_STAGE_VERTEX_BIT) builder.read(image, graph::Access::VertexSampled);
  if (stages & VK_SHADER_STAGE_GEOMETRY_BIT) builder.read(image, graph::Access::GeometrySampled);
  if (stages & VK_SHADER_STAGE_FRAGMENT_BIT) builder.read(image, graph::Access::FragmentSampled);
  entries_.push_back({binding, image, sampler, {}});
}

void PassBindings::bind_uniform(uint32_t binding, const vk::UniformSlice& slice) {
  layout_entry(binding, vk::DescriptorKind::UniformBuffer);
  entries_.push_back({binding, {}, VK_NULL_HANDLE, slice});
}

void PassBindings::bind_and_push(const graph::PassContext& ctx) const {
  if (entries_.size() != pipeline_->bindings().size())
    throw std::logic_error(pipeline_->name() + ": " + std::to_string(entries_.size()) + " of its " +
                           std::to_string(pipeline_->bindings().size()) + " bindings were declared");
  pipeline_->bind(ctx.cmd, ctx.width, ctx.height);
  for (const Entry& e : entries_) {
    if (e.image.valid())
      pipeline_->push_image(ctx.cmd, e.binding, ctx.image(e.image).sampled_view(), e.sampler);
    else
      pipeline_->push_uniform(ctx.cmd, e.binding, e.uniform.buffer, e.uniform.offset, e.uniform.size);
  }
}

}  // namespace engine::passes
