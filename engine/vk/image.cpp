#include "engine/vk/image.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_helpers.h"

#include <stdexcept>

namespace engine::vk {

bool is_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

bool has_stencil(VkFormat format) {
  return format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

uint32_t format_texel_size(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32_UINT:
      return 4;
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_D16_UNORM:
      return 2;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      throw std::invalid_argument("format_texel_size: unsupported format " + std::to_string(format));
  }
}

Image::Image(Context& context, const ImageDesc& desc, const std::string& name)
    : desc_(desc), name_(name) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.kind == ImageKind::Image3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, desc.kind == ImageKind::Image3D ? desc.depth_or_layers : 1};
  info.mipLevels = 1;
  info.arrayLayers = desc.kind == ImageKind::Image2DArray ? desc.depth_or_layers : 1;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  // A 3D image whose slices are rendered as layers of a 2D-array view (layered rendering).
  if (desc.kind == ImageKind::Image3D && (desc.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
    info.flags |= VK_IMAGE_CREATE_2D_ARRAY_COMPATIBLE_BIT;

  const VkDevice device = context.device();
  VkImage image = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  objects_->image = {device, image, vkDestroyImage};
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device, image, &requirements);
  objects_->memory = allocate_memory(
      context, requirements.size,
      context.find_memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
  VK_CHECK(vkBindImageMemory(device, image, objects_->memory.get(), 0));
  create_views(context);
  context.set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image), name);
}

Image Image::wrap(Context& context, VkImage image, const ImageDesc& desc, const std::string& name,
                  const ImageSyncState& state) {
  if (image == VK_NULL_HANDLE) throw std::invalid_argument("Image::wrap: '" + name + "' is a null VkImage");
  Image wrapped;
  wrapped.desc_ = desc;
  wrapped.name_ = name;
  wrapped.sync_ = state;
  // Borrowed: destroying the wrapper leaves the host's image alone.
  wrapped.objects_->image = {context.device(), image, [](VkDevice, VkImage, const VkAllocationCallbacks*) {}};
  wrapped.create_views(context);
  return wrapped;
}

void Image::create_views(Context& context) {
  const VkDevice device = context.device();
  const ImageDesc& desc = desc_;
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = objects_->image.get();
  view.format = desc.format;
  view.subresourceRange = full_range();
  view.viewType = desc.kind == ImageKind::Image3D        ? VK_IMAGE_VIEW_TYPE_3D
                  : desc.kind == ImageKind::Image2DArray ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                         : VK_IMAGE_VIEW_TYPE_2D;
  auto create_view = [&](VkImageAspectFlags aspects) {
    view.subresourceRange.aspectMask = aspects;
    VkImageView handle = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &view, nullptr, &handle));
    return UniqueHandle<VkImageView>(device, handle, vkDestroyImageView);
  };
  // A sampled view shows one aspect (the depth of a depth/stencil image); an attachment view all.
  if (desc.usage & (VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT))
    objects_->sampled_view = create_view(aspect());
  if (desc.usage & (VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
    if (desc.kind == ImageKind::Image3D) {
      view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
      view.subresourceRange.layerCount = desc.depth_or_layers;
    }
    objects_->attachment_view = create_view(full_range().aspectMask);
  }
}

VkImageAspectFlags Image::aspect() const {
  return is_depth_format(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImageSubresourceRange Image::full_range() const {
  const VkImageAspectFlags all = has_stencil(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT
                                                           : aspect();
  return {all, 0, 1, 0, desc_.kind == ImageKind::Image2DArray ? desc_.depth_or_layers : 1};
}

}  // namespace engine::vk
