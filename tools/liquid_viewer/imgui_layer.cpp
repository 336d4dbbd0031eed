#include "tools/liquid_viewer/imgui_layer.h"

#include "engine/vk/commands.h"
#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "tools/liquid_viewer/swapchain.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace viewer {
namespace {

void check_imgui_result(VkResult result) {
  if (result < 0) throw std::runtime_error("ImGui Vulkan backend: VkResult " + std::to_string(int(result)));
}

}  // namespace

ImGuiLayer::ImGuiLayer(engine::vk::Context& context, GLFWwindow* window, const Swapchain& swapchain)
    : context_(context), format_(swapchain.format()) {
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool_info.maxSets = 8;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = sizes;
  VK_CHECK(vkCreateDescriptorPool(context.device(), &pool_info, nullptr, &pool_));

  // Loads the graph's frame, draws over it, leaves it for the viewer's barrier to present.
  VkAttachmentDescription color{};
  color.format = format_;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  const VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency dependencies[2]{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rp.attachmentCount = 1;
  rp.pAttachments = &color;
  rp.subpassCount = 1;
  rp.pSubpasses = &subpass;
  rp.dependencyCount = 2;
  rp.pDependencies = dependencies;
  VK_CHECK(vkCreateRenderPass(context.device(), &rp, nullptr, &render_pass_));

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left behind: the panel's place lasts the session
  ImGui::GetIO().ConfigWindowsMoveFromTitleBarOnly = true;  // a drag on the panel's body is a slider's
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForVulkan(window, true);  // chains the window's own callbacks
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physical_device();
  info.Device = context.device();
  info.QueueFamily = context.queue_family();
  info.Queue = context.queue();
  info.DescriptorPool = pool_;
  info.MinImageCount = swapchain.min_image_count();
  info.ImageCount = std::max(swapchain.image_count(), swapchain.min_image_count());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = check_imgui_result;
  ImGui_ImplVulkan_Init(&info, render_pass_);

  {
    engine::vk::CommandBuffer upload(context);
    ImGui_ImplVulkan_CreateFontsTexture(upload.begin());
    upload.submit_and_wait();
  }
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  create_framebuffers(swapchain);
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  destroy_framebuffers();
  vkDestroyRenderPass(context_.device(), render_pass_, nullptr);
  vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
}

void ImGuiLayer::create_framebuffers(const Swapchain& swapchain) {
  if (swapchain.format() != format_) throw std::runtime_error("the swapchain changed its format");
  extent_ = swapchain.extent();
  for (uint32_t i = 0; i < swapchain.image_count(); ++i) {
    const VkImageView view = const_cast<Swapchain&>(swapchain).image(i).attachment_view();
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = render_pass_;
    fb.attachmentCount = 1;
    fb.pAttachments = &view;
    fb.width = extent_.width;
    fb.height = extent_.height;
    fb.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(context_.device(), &fb, nullptr, &framebuffer));
    framebuffers_.push_back(framebuffer);
  }
}

void ImGuiLayer::destroy_framebuffers() {
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(context_.device(), f, nullptr);
  framebuffers_.clear();
}

void ImGuiLayer::on_swapchain_recreated(const Swapchain& swapchain) {
  destroy_framebuffers();
  ImGui_ImplVulkan_SetMinImageCount(swapchain.min_image_count());
  create_framebuffers(swapchain);
}

void ImGuiLayer::new_frame(const ScriptedPointer* pointer) {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (pointer) {  // after the backend, which reads the window's pointer into the same fields
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(pointer->x, pointer->y);
    for (int i = 0; i < 3; ++i) io.MouseDown[i] = pointer->down[i];
    io.MouseWheel += pointer->wheel;
  }
  ImGui::NewFrame();
}

void ImGuiLayer::skip() { ImGui::EndFrame(); }

void ImGuiLayer::record(VkCommandBuffer cmd, uint32_t index) {
  ImGui::Render();
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_;
  begin.framebuffer = framebuffers_.at(index);
  begin.renderArea.extent = extent_;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace viewer
