// The viewer's GLFW window: created without a client API (Vulkan presents into it), its input
// turned into InputEvents, and the instance extensions and presentation test the context needs.
#pragma once

#include "tools/liquid_viewer/input.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace viewer {

class Window {
 public:
  // Throws std::runtime_error with one line ("no display: ...") when GLFW finds no X server.
  Window(const std::string& title, uint32_t width, uint32_t height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  // VK_KHR_surface and the platform's surface extension.
  static std::vector<const char*> instance_extensions();
  static bool can_present(VkInstance instance, VkPhysicalDevice device, uint32_t queue_family);
  VkSurfaceKHR create_surface(VkInstance instance) const;

  bool should_close() const { return glfwWindowShouldClose(window_); }
  void request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
  // Framebuffer size in pixels (0 x 0 while minimized).
  void framebuffer_size(uint32_t& width, uint32_t& height) const;
  void set_size(uint32_t width, uint32_t height);
  void set_title(const std::string& title);

  // Every input event since the last call (the callbacks queue them).
  std::vector<InputEvent> take_events();

 private:
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_button(GLFWwindow* w, int button, int action, int mods);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);

  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> events_;
};

}  // namespace viewer
