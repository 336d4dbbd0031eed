// The descriptor bindings of one raster pass, written once. The pipeline's binding table (its
// GraphicsPipelineDesc::bindings) says which stage reads each binding; a pass's setup declares each
// graph image through bind_image(), which both declares the graph read (its Access follows from
// that stage) and remembers the binding, and its record function calls push(), which writes
// exactly those descriptors. A binding of the table that the setup did not bind is an error.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/uniform_arena.h"

#include <vector>

namespace engine::passes {

class PassBindings {
 public:
  PassBindings() = default;
  explicit PassBindings(const vk::GraphicsPipeline& pipeline) : pipeline_(&pipeline) {}

  // Declares that the pass's shaders sample `image` at `binding` with `sampler`.
  void bind_image(graph::PassBuilder& builder, uint32_t binding, graph::ImageHandle image, VkSampler sampler);
  // A uniform block (a slice of a UniformArena) at `binding`.
  void bind_uniform(uint32_t binding, const vk::UniformSlice& slice);

  // Binds the pipeline with a full viewport of the pass's render area and pushes every binding.
  void bind_and_push(const graph::PassContext& ctx) const;

 private:
  struct Entry {
    uint32_t binding;
    graph::ImageHandle image;  // sampled image, or
    VkSampler sampler = VK_NULL_HANDLE;
    vk::UniformSlice uniform;  // a uniform block
  };
  const vk::DescriptorBinding& layout_entry(uint32_t binding, vk::DescriptorKind kind) const;

  const vk::GraphicsPipeline* pipeline_ = nullptr;
  std::vector<Entry> entries_;
};

}  // namespace engine::passes
