// Dear ImGui over the swapchain image, after the render graph: the GLFW and Vulkan backends
// (compiled from the sources Debian's libimgui-dev ships), a render pass that loads what the graph
// left in the image, and one framebuffer per swapchain image.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

struct GLFWwindow;

namespace engine::vk {
class Context;
}

namespace viewer {

class Swapchain;

// The mouse as a replayed script leaves it, for ImGui in place of the window's real pointer.
struct ScriptedPointer {
  float x = 0.0f, y = 0.0f;  // window pixels
  bool down[3] = {false, false, false};  // left, right, middle (ImGui's order)
  float wheel = 0.0f;  // clicks since the last frame
};

class ImGuiLayer {
 public:
  ImGuiLayer(engine::vk::Context& context, GLFWwindow* window, const Swapchain& swapchain);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // After the swapchain was recreated (device idle): new framebuffers.
  void on_swapchain_recreated(const Swapchain& swapchain);
  // Starts a frame of ImGui calls; with `pointer`, ImGui sees that mouse instead of the window's.
  void new_frame(const ScriptedPointer* pointer = nullptr);
  // Ends the frame and records its drawing into swapchain image `index`, which must be in
  // COLOR_ATTACHMENT_OPTIMAL with its earlier writes made visible to colour-attachment access;
  // it is left there, its writes done by COLOR_ATTACHMENT_OUTPUT.
  void record(VkCommandBuffer cmd, uint32_t index);
  // Ends the frame without drawing (the panel is hidden).
  void skip();
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  void create_framebuffers(const Swapchain& swapchain);
  void destroy_framebuffers();

  engine::vk::Context& context_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{0, 0};
  std::vector<VkFramebuffer> framebuffers_;
};

}  // namespace viewer
