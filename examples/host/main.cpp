// liquid_host: a host engine using RasterLiquids as a game engine would. It owns the Vulkan
// instance, device and queue, its colour and depth targets and its scene (a floor and a box
// standing in the water), and each frame adds the liquid to its own command buffer:
//   host pass (plain Vulkan) -> liquid node (splat, grid, particle per step) -> liquid renderer
//   composited into the host's targets with its depth -> FXAA -> readback -> PNG.
// Two frames are in flight, each with its own render graph, command buffer and fence.
//   liquid_host SCENE.json [--frames N] [--steps-per-frame K] [--width W] [--height H] [--out DIR] [--validation]
#include "host_vulkan.h"
#include "scene_pass.h"

#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/io/png.h"
#include "engine/vk/context.h"
#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/scene.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

struct Options {
  std::string scene;
  int frames = 90;            // 3 s at 30 frames per second
  int steps_per_frame = 0;    // 0: the scene's substeps (1/30 s of simulated time)
  uint32_t width = 640, height = 480;
  std::filesystem::path out = "host_frames";
  bool validation = false;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--frames") o.frames = std::stoi(value());
    else if (a == "--steps-per-frame") o.steps_per_frame = std::stoi(value());
    else if (a == "--width") o.width = uint32_t(std::stoul(value()));
    else if (a == "--height") o.height = uint32_t(std::stoul(value()));
    else if (a == "--out") o.out = value();
    else if (a == "--validation") o.validation = true;
    else if (!a.empty() && a[0] != '-' && o.scene.empty()) o.scene = a;
    else throw std::invalid_argument("unknown argument " + a);
  }
  if (o.scene.empty()) throw std::invalid_argument("usage: liquid_host SCENE.json [--frames N] ...");
  if (o.frames < 1 || o.width < 16 || o.height < 16) throw std::invalid_argument("--frames, --width or --height out of range");
  return o;
}

// One frame in flight: its own graph (transient images are reused only after its fence), command
// buffer and fence, and the readback it will write as a PNG once the fence signals.
struct FrameSlot {
  FrameSlot(engine::vk::Context& context) : graph(&context) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool(context);
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    host_check(vkAllocateCommandBuffers(context.device(), &alloc, &cmd), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    host_check(vkCreateFence(context.device(), &fence_info, nullptr, &fence), "vkCreateFence");
    device = context.device();
  }
  ~FrameSlot() { vkDestroyFence(device, fence, nullptr); }
  static VkCommandPool pool(engine::vk::Context& context) { return context.command_pool(); }

  engine::graph::RenderGraph graph;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::optional<engine::graph::Readback> shot;
  int frame = -1;
};

std::filesystem::path frame_path(const Options& o, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return o.out / name;
}

int run(const Options& o) {
  HostVulkan vulkan(o.validation);
  engine::vk::Context context(vulkan.host_device());

  // The scene, with a box standing in the water's path: an obstacle for the liquid, geometry for
  // the host (both from the same numbers).
  liquid::Scene scene = liquid::load_scene(o.scene);
  if (scene.dimension != 3) throw std::invalid_argument(o.scene + ": the host example composites a 3D scene");
  liquid::Obstacle box;
  box.shape = liquid::ObstacleShape::Box;
  box.half_extent = {0.05f * scene.domain.x, 0.3f * scene.domain.y, 0.12f * scene.domain.z};
  box.center = {0.5f * scene.domain.x, box.half_extent.y, 0.5f * scene.domain.z};
  scene.obstacles.push_back(box);
  constexpr uint32_t k_frames_in_flight = 2;
  liquid::LiquidNode node(context, scene, liquid::LiquidOptions{.frames_in_flight = k_frames_in_flight});
  liquid::LiquidRenderer renderer(
      context, node, liquid::RenderSettings{.width = o.width, .height = o.height, .composite = true});
  const liquid::CameraView camera = liquid::default_camera(node);
  const glm::mat4 view_projection = renderer.view_projection(camera);  // the host draws with the same matrix
  ScenePass scene_pass(context);

  HostImage color_image(vulkan.physical_device, vulkan.device, o.width, o.height, liquid::k_color_format,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  HostImage depth_image(vulkan.physical_device, vulkan.device, o.width, o.height, liquid::k_depth_format,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  using engine::vk::ImageDesc;
  using engine::vk::ImageKind;
  engine::vk::Image color = engine::vk::Image::wrap(
      context, color_image.image,
      ImageDesc{ImageKind::Image2D, o.width, o.height, 1, liquid::k_color_format,
                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
      "host.color", {});
  engine::vk::Image depth = engine::vk::Image::wrap(
      context, depth_image.image,
      ImageDesc{ImageKind::Image2D, o.width, o.height, 1, liquid::k_depth_format,
                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
      "host.depth", {});

  std::filesystem::create_directories(o.out);
  std::array<std::unique_ptr<FrameSlot>, k_frames_in_flight> slots;
  for (auto& slot : slots) slot = std::make_unique<FrameSlot>(context);
  auto finish = [&](FrameSlot& slot) {  // waits for the slot's frame and writes its PNG
    host_check(vkWaitForFences(context.device(), 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    if (slot.shot) engine::vk::write_png(frame_path(o, slot.frame), slot.shot->rgba8());
    slot.shot.reset();
  };
  const int steps = o.steps_per_frame > 0 ? o.steps_per_frame : node.substeps();
  for (int frame = 0; frame < o.frames; ++frame) {
    FrameSlot& slot = *slots[size_t(frame) % k_frames_in_flight];
    // The frame contract: the frame that last used this slot (k_frames_in_flight frames ago) has
    // finished before its graph, and the node's uniform region of that frame, are reused.
    finish(slot);
    host_check(vkResetFences(context.device(), 1, &slot.fence), "vkResetFences");
    host_check(vkResetCommandBuffer(slot.cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    host_check(vkBeginCommandBuffer(slot.cmd, &begin), "vkBeginCommandBuffer");

    scene_pass.record(slot.cmd, color, depth, view_projection, box.center, box.half_extent,
                      glm::vec2(scene.domain.x, scene.domain.z));
    engine::graph::RenderGraph& graph = slot.graph;
    graph.reset();
    const engine::graph::ImageHandle host_color = graph.import_image("host.color", color);
    const engine::graph::ImageHandle host_depth = graph.import_image("host.depth", depth);
    const liquid::LiquidImages images = node.add_to(graph, steps);
    const liquid::RenderOutputs out = renderer.add_to(graph, images, camera, {host_color, host_depth});
    slot.shot = engine::graph::add_readback(graph, out.final, "host.readback");
    slot.frame = frame;
    graph.compile();
    graph.execute(slot.cmd);  // recorded into the host's own command buffer
    host_check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer");

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &slot.cmd;
    host_check(vkQueueSubmit(vulkan.queue, 1, &submit, slot.fence), "vkQueueSubmit");
    std::printf("frame %d: t = %.3f s, %d particles\n", frame, node.time(), node.active_particles());
  }
  for (auto& slot : slots) finish(*slot);
  // Reads need no frame of the node in flight: every fence has signalled.
  const liquid::Diagnostics d = node.diagnose();
  std::printf("liquid_host: %d frames in %s, %d particles, %d inside the box, %u validation message(s)\n", o.frames,
              o.out.string().c_str(), d.active_particles, d.inside_obstacles, context.validation_message_count());
  for (auto& slot : slots) vkFreeCommandBuffers(context.device(), context.command_pool(), 1, &slot->cmd);
  return context.validation_message_count() == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "liquid_host: error: %s\n", error.what());
    return 1;
  }
}
