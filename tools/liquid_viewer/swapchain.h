// The window's swapchain: format and present mode chosen once, images wrapped as graph images
// (engine::vk::Image::wrap), one "rendering done" semaphore per image, recreated on resize.
#pragma once

#include "engine/vk/image.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace engine::vk {
class Context;
}

namespace viewer {

class Swapchain {
 public:
  // `unthrottled`: MAILBOX, else IMMEDIATE, else FIFO; otherwise FIFO (always available).
  Swapchain(engine::vk::Context& context, VkSurfaceKHR surface, bool unthrottled);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // (Re)creates the swapchain at the surface's current extent (or `width` x `height` where the
  // surface leaves it to us). The device must be idle. Returns false while the window has no
  // area (minimized).
  bool recreate(uint32_t width, uint32_t height);

  VkSwapchainKHR handle() const { return swapchain_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  VkPresentModeKHR present_mode() const { return present_mode_; }
  uint32_t image_count() const { return uint32_t(images_.size()); }
  uint32_t min_image_count() const { return min_image_count_; }
  engine::vk::Image& image(uint32_t index) { return *images_[index]; }
  VkSemaphore rendered(uint32_t index) const { return rendered_[index]; }
  uint32_t recreations() const { return recreations_; }
  // Colour channels are stored B, G, R, A (the PNG writer wants R, G, B, A).
  bool bgra() const;

 private:
  void destroy_images();

  engine::vk::Context& context_;
  VkSurfaceKHR surface_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR color_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{0, 0};
  uint32_t min_image_count_ = 2;
  uint32_t recreations_ = 0;
  bool recreated_once_ = false;
  std::vector<std::unique_ptr<engine::vk::Image>> images_;
  std::vector<VkSemaphore> rendered_;
};

const char* present_mode_name(VkPresentModeKHR mode);

}  // namespace viewer
