#include "engine/vk/image.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

#include <stdexcept>
#include <utility>

namespace engine::vk {

bool is_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
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
    : context_(&context), desc_(desc), name_(name) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.kind == ImageKind::Image3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, desc.kind == ImageKind::Image3D ? desc.depth_or_layers : 1};
  info.mipLevels = 1;
  info.arrayLayers = desc.kind == ImageKind::Image2DArray ? desc.depth_or_layers : 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  // A 3D image whose slices are rendered as layers of a 2D-array view (layered rendering).
  if (desc.kind == ImageKind::Image3D && (desc.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
    info.flags |= VK_IMAGE_CREATE_2D_ARRAY_COMPATIBLE_BIT;

  const VkDevice device = context.device();
  try {
    VK_CHECK(vkCreateImage(device, &info, nullptr, &image_));
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device, image_, &requirements);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    alloc.memoryTypeIndex =
        context.find_memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &memory_));
    VK_CHECK(vkBindImageMemory(device, image_, memory_, 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.format = desc.format;
    view.subresourceRange = full_range();
    view.viewType = desc.kind == ImageKind::Image3D        ? VK_IMAGE_VIEW_TYPE_3D
                    : desc.kind == ImageKind::Image2DArray ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                           : VK_IMAGE_VIEW_TYPE_2D;
    if (desc.usage & (VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT))
      VK_CHECK(vkCreateImageView(device, &view, nullptr, &sampled_view_));
    if (desc.usage & (VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
      if (desc.kind == ImageKind::Image3D) {
        view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        view.subresourceRange.layerCount = desc.depth_or_layers;
      }
      VK_CHECK(vkCreateImageView(device, &view, nullptr, &attachment_view_));
    }
  } catch (...) {
    release();
    throw;
  }
  context.set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image_), name);
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    sampled_view_ = std::exchange(other.sampled_view_, VK_NULL_HANDLE);
    attachment_view_ = std::exchange(other.attachment_view_, VK_NULL_HANDLE);
    desc_ = other.desc_;
    name_ = std::move(other.name_);
    sync_ = other.sync_;
  }
  return *this;
}

void Image::release() {
  if (!context_) return;
  const VkDevice device = context_->device();
  if (attachment_view_) vkDestroyImageView(device, attachment_view_, nullptr);
  if (sampled_view_) vkDestroyImageView(device, sampled_view_, nullptr);
  if (image_) vkDestroyImage(device, image_, nullptr);
  if (memory_) vkFreeMemory(device, memory_, nullptr);
  attachment_view_ = sampled_view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  context_ = nullptr;
}

VkImageAspectFlags Image::aspect() const {
  return is_depth_format(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImageSubresourceRange Image::full_range() const {
  return {aspect(), 0, 1, 0, desc_.kind == ImageKind::Image2DArray ? desc_.depth_or_layers : 1};
}

}  // namespace engine::vk
