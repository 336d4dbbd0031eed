#include "tools/liquid_viewer/window.h"

#include <stdexcept>

namespace viewer {
namespace {

std::string g_last_error;

void on_glfw_error(int, const char* description) { g_last_error = description ? description : "unknown GLFW error"; }

Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }

}  // namespace

Window::Window(const std::string& title, uint32_t width, uint32_t height) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit())
    throw std::runtime_error("no display: " + (g_last_error.empty() ? std::string("GLFW could not start") : g_last_error));
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw std::runtime_error("GLFW finds no Vulkan loader");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("cannot create a window: " + g_last_error);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetCursorPosCallback(window_, on_cursor);
  glfwSetMouseButtonCallback(window_, on_button);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetKeyCallback(window_, on_key);
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<const char*> Window::instance_extensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw std::runtime_error("GLFW knows no Vulkan surface extension for this display: " + g_last_error);
  return {names, names + count};
}

bool Window::can_present(VkInstance instance, VkPhysicalDevice device, uint32_t queue_family) {
  return glfwGetPhysicalDevicePresentationSupport(instance, device, queue_family) == GLFW_TRUE;
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS)
    throw std::runtime_error("cannot create a Vulkan surface for the window: " + g_last_error);
  return surface;
}

void Window::framebuffer_size(uint32_t& width, uint32_t& height) const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  width = uint32_t(std::max(w, 0));
  height = uint32_t(std::max(h, 0));
}

void Window::set_size(uint32_t width, uint32_t height) { glfwSetWindowSize(window_, int(width), int(height)); }
void Window::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

std::vector<InputEvent> Window::take_events() {
  std::vector<InputEvent> events;
  events.swap(events_);
  return events;
}

void Window::on_cursor(GLFWwindow* w, double x, double y) {
  self(w)->events_.push_back({InputEvent::Type::Move, float(x), float(y)});
}

void Window::on_button(GLFWwindow* w, int button, int action, int mods) {
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  InputEvent e{action == GLFW_PRESS ? InputEvent::Type::Press : InputEvent::Type::Release, float(x), float(y)};
  e.button = button == GLFW_MOUSE_BUTTON_LEFT ? MouseButton::Left
             : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right : MouseButton::Middle;
  e.mods = mods;
  self(w)->events_.push_back(e);
}

void Window::on_scroll(GLFWwindow* w, double, double dy) {
  InputEvent e{InputEvent::Type::Scroll};
  e.scroll = float(dy);
  if (glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS)
    e.mods |= GLFW_MOD_CONTROL;
  if (glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS)
    e.mods |= GLFW_MOD_SHIFT;
  self(w)->events_.push_back(e);
}

void Window::on_key(GLFWwindow* w, int key, int, int action, int mods) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  InputEvent e{InputEvent::Type::Key};
  e.key = key;
  e.mods = mods;
  self(w)->events_.push_back(e);
}

}  // namespace viewer
