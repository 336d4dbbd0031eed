#include "tools/liquid_viewer/swapchain.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace viewer {
namespace {

// The liquid renderer writes RGBA8 UNORM; the present pass draws it into the swapchain image, whose
// format converts the channel order. A UNORM format keeps the renderer's values as they are (an
// SRGB one would encode them a second time), so UNORM formats come first.
VkSurfaceFormatKHR pick_format(const std::vector<VkSurfaceFormatKHR>& formats) {
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const auto& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
    for (const auto& f : formats)
      if (f.format == wanted) return f;
  throw std::runtime_error("the window offers no 8-bit RGBA or BGRA swapchain format");
}

}  // namespace

const char* present_mode_name(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR: return "FIFO";
    case VK_PRESENT_MODE_MAILBOX_KHR: return "MAILBOX";
    case VK_PRESENT_MODE_IMMEDIATE_KHR: return "IMMEDIATE";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR: return "FIFO_RELAXED";
    default: return "other";
  }
}

Swapchain::Swapchain(engine::vk::Context& context, VkSurfaceKHR surface, bool unthrottled)
    : context_(context), surface_(surface) {
  const VkPhysicalDevice pd = context.physical_device();
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &count, formats.data()));
  const VkSurfaceFormatKHR chosen = pick_format(formats);
  format_ = chosen.format;
  color_space_ = chosen.colorSpace;

  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface, &count, modes.data()));
  present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  if (unthrottled) {
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
      if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) {
        present_mode_ = wanted;
        break;
      }
  }
}

Swapchain::~Swapchain() {
  destroy_images();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
}

bool Swapchain::bgra() const { return format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB; }

void Swapchain::destroy_images() {
  for (VkSemaphore s : rendered_) vkDestroySemaphore(context_.device(), s, nullptr);
  rendered_.clear();
  images_.clear();
}

bool Swapchain::recreate(uint32_t width, uint32_t height) {
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device(), surface_, &caps));
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) {
    extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return false;

  constexpr VkImageUsageFlags k_usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if ((caps.supportedUsageFlags & k_usage) != k_usage)
    throw std::runtime_error("the swapchain cannot be a transfer source, destination and colour attachment");
  min_image_count_ = std::max(caps.minImageCount + 1, 3u);
  if (caps.maxImageCount > 0) min_image_count_ = std::min(min_image_count_, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = min_image_count_;
  info.imageFormat = format_;
  info.imageColorSpace = color_space_;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = k_usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = present_mode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &created));
  destroy_images();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  swapchain_ = created;
  extent_ = extent;
  if (recreated_once_) ++recreations_;
  recreated_once_ = true;

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr));
  std::vector<VkImage> handles(count);
  VK_CHECK(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, handles.data()));
  for (uint32_t i = 0; i < count; ++i) {
    const engine::vk::ImageDesc desc{engine::vk::ImageKind::Image2D, extent.width, extent.height, 1, format_, k_usage};
    images_.push_back(std::make_unique<engine::vk::Image>(engine::vk::Image::wrap(
        context_, handles[i], desc, "swapchain." + std::to_string(i), engine::vk::ImageSyncState{})));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(context_.device(), &semaphore, nullptr, &s));
    rendered_.push_back(s);
  }
  return true;
}

}  // namespace viewer
