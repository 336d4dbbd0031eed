// One frame in flight: its own render graph (transient images are reused only after its fence),
// command buffer, fence and "image acquired" semaphore, and the screenshot it copies out of the
// swapchain image, written once the fence has signalled. Plus the barrier the viewer records by
// hand after the graph (ImGui's render pass, the copy, the present), from the image's sync state.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"

#include <vulkan/vulkan.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace engine::vk {
class Context;
}

namespace viewer {

struct Shot {
  std::shared_ptr<engine::vk::Buffer> buffer;
  uint32_t width = 0, height = 0;
  bool bgra = false;
  std::filesystem::path path;
};

class FrameSlot {
 public:
  explicit FrameSlot(engine::vk::Context& context);
  ~FrameSlot();
  FrameSlot(const FrameSlot&) = delete;
  FrameSlot& operator=(const FrameSlot&) = delete;

  // Waits until the GPU has finished this slot's last frame, then writes its screenshot.
  void wait();
  // Resets the fence and begins recording.
  VkCommandBuffer begin();

  engine::graph::RenderGraph graph;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSemaphore acquired = VK_NULL_HANDLE;
  std::optional<Shot> shot;
  bool submitted = false;  // the graph has executed and its timings can be read

 private:
  engine::vk::Context& context_;
};

// A barrier of `image` from where its sync state says it is to `layout` for the given use, and
// the state updated to match (a write when `writes`). Written by hand, not through the graph,
// because these uses come after graph.execute() in the same command buffer and are not graph
// passes: Dear ImGui's Vulkan backend records its own rendering into the swapchain image, the
// screenshot copy exists only on the frames that take one, and PRESENT_SRC is a layout the graph's
// Access table has no use for. The graph's own barriers still come from the image's sync state,
// which this keeps up to date, so the next frame's graph starts from where this left the image.
void transition(VkCommandBuffer cmd, engine::vk::Image& image, VkImageLayout layout, VkPipelineStageFlags2 stages,
                VkAccessFlags2 access, bool writes);

// Records a copy of the whole image (in TRANSFER_SRC_OPTIMAL) into a new host-visible buffer.
Shot copy_to_buffer(engine::vk::Context& context, VkCommandBuffer cmd, engine::vk::Image& image, bool bgra,
                    const std::filesystem::path& path);

}  // namespace viewer
