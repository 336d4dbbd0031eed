// RAII image with its memory and views, plus the synchronization state the render graph keeps
// for it between graph executions (an imported, persistent image remembers its last access).
#pragma once

#include "engine/vk/device_memory.h"
#include "engine/vk/handle.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace engine::vk {

class Context;

enum class ImageKind {
  Image2D,       // width x height
  Image2DArray,  // width x height x layers
  Image3D,       // width x height x depth; created 2D_ARRAY_COMPATIBLE so passes render into slices
};

struct ImageDesc {
  ImageKind kind = ImageKind::Image2D;
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t depth_or_layers = 1;  // depth for Image3D, layers for Image2DArray, 1 for Image2D
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageUsageFlags usage = 0;
  // More than one: a multisampled image (a host's MSAA target, wrapped); its passes must agree.
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;

  // Layers a pass renders into: slices of a 3D image, layers of an array.
  uint32_t render_layers() const { return kind == ImageKind::Image2D ? 1 : depth_or_layers; }
  bool operator==(const ImageDesc&) const = default;
};

// Where an image stands in the pipeline: its layout, the last write not yet made visible to every
// later use, and the stages that read it since. The graph derives barriers from this.
struct ImageSyncState {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 write_stages = 0;
  VkAccessFlags2 write_access = 0;
  VkPipelineStageFlags2 read_stages = 0;  // readers since the last write
  VkAccessFlags2 read_access = 0;
  VkPipelineStageFlags2 visible_stages = 0;  // stages that already see the last write

  // An image in `layout` whose last use was a write by `stages` with `access` (for example a host's
  // colour target just rendered: COLOR_ATTACHMENT_OPTIMAL, COLOR_ATTACHMENT_OUTPUT,
  // COLOR_ATTACHMENT_WRITE). The graph's first use waits for that write.
  static ImageSyncState after_write(VkImageLayout layout, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    return {layout, stages, access, 0, 0, 0};
  }
  // An image in `layout` whose writes are all visible, last read by `stages` (or never used:
  // UNDEFINED with no stages, e.g. a swapchain image just acquired).
  static ImageSyncState after_read(VkImageLayout layout, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    return {layout, 0, 0, stages, access, 0};
  }
};

bool is_depth_format(VkFormat format);
// D24_UNORM_S8_UINT, D32_SFLOAT_S8_UINT: a depth format whose stencil travels with it (its
// barriers cover both aspects, its attachment layout is DEPTH_STENCIL_ATTACHMENT_OPTIMAL).
bool has_stencil(VkFormat format);
uint32_t format_texel_size(VkFormat format);

class Image {
 public:
  Image() = default;
  Image(Context& context, const ImageDesc& desc, const std::string& name);

  // A host-owned VkImage (its colour or depth target, a swapchain image) made usable by the graph:
  // the views are created and owned here, the image and its memory stay the host's and must
  // outlive this object. `desc.usage` is the usage the host created it with; `state` is where the
  // host left it. The graph updates sync_state() as it runs, so after the frame the host reads the
  // layout and last access it was left in.
  static Image wrap(Context& context, VkImage image, const ImageDesc& desc, const std::string& name,
                    const ImageSyncState& state);
  bool owns_memory() const { return bool(objects_->memory); }

  VkImage handle() const { return objects_->image.get(); }
  // View for sampling: 2D, 2D_ARRAY or 3D matching the kind.
  VkImageView sampled_view() const { return objects_->sampled_view.get(); }
  // View for rendering: 2D for Image2D, 2D_ARRAY over every layer or slice otherwise.
  VkImageView attachment_view() const { return objects_->attachment_view.get(); }
  const ImageDesc& desc() const { return desc_; }
  const std::string& name() const { return name_; }
  // The aspect sampled and copied: depth for a depth format (its stencil stays where it is).
  VkImageAspectFlags aspect() const;
  // Every aspect and layer: what a barrier covers (depth and stencil for a combined format).
  VkImageSubresourceRange full_range() const;

  ImageSyncState& sync_state() { return sync_; }
  const ImageSyncState& sync_state() const { return sync_; }

 private:
  struct Objects {
    DeviceMemory memory;  // counted against the context (memory_in_use)
    UniqueHandle<VkImage> image;  // bound to memory
    UniqueHandle<VkImageView> sampled_view;
    UniqueHandle<VkImageView> attachment_view;
  };

  void create_views(Context& context);

  HandleGroup<Objects> objects_;
  ImageDesc desc_{};
  std::string name_;
  ImageSyncState sync_{};
};

}  // namespace engine::vk
