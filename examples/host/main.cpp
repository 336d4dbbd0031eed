// liquid_host: a host engine using RasterLiquids as a game engine would. It owns the Vulkan
// instance, device and queue, its targets, its camera and its scene (a floor and a paddle turning in
// the water, a mesh of its own that it also gives the liquid), and each frame adds the liquid to its
// own command buffer:
//   host scene pass (plain Vulkan: HDR colour, reversed-Z depth, its own orbiting camera)
//   -> liquid node (splat, grid, particle per step) -> liquid renderer, composited into the HDR
//      scene through the host's camera, the tank placed rotated in the host's world
//   -> the host's tone map (a pass of its own on the same graph) into the display image
//   -> a 2D liquid (a second node) composited as a panel in a corner of the display -> PNG.
// Two frames are in flight, each with its own render graph, command buffer and fence.
//   liquid_host SCENE.json [--panel SCENE_2D.json] [--frames N] [--steps-per-frame K] [--width W]
//               [--height H] [--out DIR] [--validation]
#include "host_mesh.h"
#include "host_vulkan.h"
#include "scene_pass.h"
#include "tone_map_pass.h"

#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/io/png.h"
#include "engine/vk/context.h"
#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace {

struct Options {
  std::string scene;
  std::string panel;          // a 2D scene drawn in a corner; empty: none
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
    if (a == "--panel") o.panel = value();
    else if (a == "--frames") o.frames = std::stoi(value());
    else if (a == "--steps-per-frame") o.steps_per_frame = std::stoi(value());
    else if (a == "--width") o.width = uint32_t(std::stoul(value()));
    else if (a == "--height") o.height = uint32_t(std::stoul(value()));
    else if (a == "--out") o.out = value();
    else if (a == "--validation") o.validation = true;
    else if (!a.empty() && a[0] != '-' && o.scene.empty()) o.scene = a;
    else throw std::invalid_argument("unknown argument " + a);
  }
  if (o.scene.empty()) throw std::invalid_argument("usage: liquid_host SCENE.json [--panel SCENE_2D.json] [--frames N] ...");
  if (o.frames < 1 || o.width < 16 || o.height < 16) throw std::invalid_argument("--frames, --width or --height out of range");
  return o;
}

// The host's camera: it orbits `target`, and its projection is the host's own: reversed Z with an
// infinite far plane (depth = near / distance: 1 at the near plane, 0 at infinity), y down.
struct HostCamera {
  glm::mat4 view;
  glm::mat4 projection;
};

HostCamera orbit_camera(glm::vec3 target, float distance, float height, float angle, float aspect) {
  const glm::vec3 eye = target + glm::vec3(distance * std::sin(angle), height, distance * std::cos(angle));
  const float focal = 1.0f / std::tan(0.5f * glm::radians(50.0f)), near_plane = 0.05f;
  glm::mat4 projection(0.0f);
  projection[0][0] = focal / aspect;
  projection[1][1] = -focal;
  projection[2][3] = -1.0f;
  projection[3][2] = near_plane;
  return {glm::lookAtRH(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)), projection};
}

// A host image with its memory, wrapped for the graph.
struct HostTarget {
  HostTarget(engine::vk::Context& context, const HostVulkan& vulkan, const char* name, uint32_t width, uint32_t height,
             VkFormat format, VkImageUsageFlags usage)
      : memory(vulkan.physical_device, vulkan.device, width, height, format, usage),
        image(engine::vk::Image::wrap(
            context, memory.image,
            engine::vk::ImageDesc{engine::vk::ImageKind::Image2D, width, height, 1, format, usage}, name, {})) {}
  HostImage memory;
  engine::vk::Image image;
};

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

constexpr float k_paddle_turn_rate = 3.0f;  // rad/s about the vertical

std::filesystem::path frame_path(const Options& o, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return o.out / name;
}

int run(const Options& o) {
  HostVulkan vulkan(o.validation);
  engine::vk::Context context(vulkan.host_device());

  // The scene, with the host's paddle standing in the water's path: its own mesh, drawn by its scene
  // pass and given to the liquid from the same vertex and index bytes.
  liquid::Scene scene = liquid::load_scene(o.scene);
  if (scene.dimension != 3) throw std::invalid_argument(o.scene + ": the host example composites a 3D scene");
  const HostMesh paddle = board_mesh({0.025f * scene.domain.x, 0.3f * scene.domain.y, 0.22f * scene.domain.z});
  const glm::vec3 paddle_center{0.6f * scene.domain.x, 0.3f * scene.domain.y, 0.5f * scene.domain.z};
  scene.obstacles.push_back(liquid::mesh_obstacle(std::as_bytes(std::span(paddle.vertices)), sizeof(HostVertex),
                                                  paddle.indices, paddle_center, "the host's paddle"));
  const size_t paddle_index = scene.obstacles.size() - 1;
  constexpr uint32_t k_frames_in_flight = 2;
  liquid::LiquidNode node(context, scene, liquid::LiquidOptions{.frames_in_flight = k_frames_in_flight});
  // The tank in the host's world: turned 35 degrees about the vertical (gravity stays down), moved
  // off the world's origin. The host's camera and the node share it.
  node.set_placement({.translation = {0.8f, 0.0f, -0.6f},
                      .rotation = glm::angleAxis(glm::radians(35.0f), glm::vec3(0.0f, 1.0f, 0.0f))});
  liquid::LiquidRenderer renderer(
      context, node, liquid::RenderSettings{.width = o.width, .height = o.height, .composite = true, .exposure = 1.0f});
  const glm::mat4 floor_model = glm::scale(glm::mat4(1.0f), glm::vec3(4.0f));  // 8 m of floor around the origin
  const glm::vec3 orbit_target = node.placement().point_to_world(scene.domain * glm::vec3(0.5f, 0.25f, 0.5f));
  ScenePass scene_pass(context, vulkan, floor_mesh(), paddle);
  ToneMapPass tone_map(context);

  // An optional 2D liquid in a corner of the display, as a HUD panel.
  std::unique_ptr<liquid::LiquidNode> panel_node;
  std::unique_ptr<liquid::LiquidRenderer> panel_renderer;
  if (!o.panel.empty()) {
    const liquid::Scene panel_scene = liquid::load_scene(o.panel);
    if (panel_scene.dimension != 2) throw std::invalid_argument(o.panel + ": the panel shows a 2D scene");
    panel_node = std::make_unique<liquid::LiquidNode>(context, panel_scene,
                                                      liquid::LiquidOptions{.frames_in_flight = k_frames_in_flight});
    panel_renderer = std::make_unique<liquid::LiquidRenderer>(
        context, *panel_node, liquid::RenderSettings{.width = o.width, .height = o.height, .composite = true});
  }
  const uint32_t panel_width = o.width * 3 / 8, panel_height = o.height * 3 / 8;
  const VkRect2D panel_rect{{int32_t(o.width - panel_width - o.width / 40), int32_t(o.height / 40)},
                            {panel_width, panel_height}};

  // The host's targets: the HDR scene (linear radiance) and its reversed-Z depth, and the display
  // image the tone map writes and the panel is drawn into.
  HostTarget hdr(context, vulkan, "host.hdr", o.width, o.height, ScenePass::k_color_format,
                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  HostTarget depth(context, vulkan, "host.depth", o.width, o.height, ScenePass::k_depth_format,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  HostTarget display(context, vulkan, "host.display", o.width, o.height, ToneMapPass::k_display_format,
                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);

  std::filesystem::create_directories(o.out);
  std::array<std::unique_ptr<FrameSlot>, k_frames_in_flight> slots;
  for (auto& slot : slots) slot = std::make_unique<FrameSlot>(context);
  auto finish = [&](FrameSlot& slot) {  // waits for the slot's frame and writes its PNG
    host_check(vkWaitForFences(context.device(), 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    if (slot.shot) engine::vk::write_png(frame_path(o, slot.frame), slot.shot->rgba8());
    slot.shot.reset();
  };
  const int steps = o.steps_per_frame > 0 ? o.steps_per_frame : node.substeps();
  const float aspect = float(o.width) / float(o.height);
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

    // The paddle turns about the vertical at a steady rate; the liquid voxelizes it where the host
    // draws it (the turn is set before this frame's steps and holds through them).
    const glm::quat paddle_turn =
        glm::angleAxis(k_paddle_turn_rate * float(node.time()), glm::vec3(0.0f, 1.0f, 0.0f));
    node.set_mesh_transform(paddle_index, paddle_turn, 1.0f);
    const glm::mat4 paddle_model = node.placement().world_from_liquid() *
                                   glm::translate(glm::mat4(1.0f), paddle_center) * glm::mat4_cast(paddle_turn);
    // The host's camera turns a little each frame around the tank.
    const HostCamera camera =
        orbit_camera(orbit_target, 1.25f * glm::length(scene.domain), 0.75f * glm::length(scene.domain),
                     0.4f + 0.02f * float(frame), aspect);
    scene_pass.record(slot.cmd, hdr.image, depth.image, camera.projection * camera.view, floor_model, paddle_model);
    engine::graph::RenderGraph& graph = slot.graph;
    graph.reset();
    const engine::graph::ImageHandle host_hdr = graph.import_image("host.hdr", hdr.image);
    const engine::graph::ImageHandle host_depth = graph.import_image("host.depth", depth.image);
    const engine::graph::ImageHandle host_display = graph.import_image("host.display", display.image);
    const liquid::LiquidImages images = node.add_to(graph, steps);
    // The host's view and projection; no model: the node's placement puts the tank in the world.
    const liquid::RenderOutputs out = renderer.add_to(
        graph, images, liquid::HostView{.view = camera.view, .projection = camera.projection, .reversed_z = true},
        {host_hdr, host_depth});
    engine::graph::ImageHandle shown =
        tone_map.add_to(graph, out.final, host_display, panel_node ? panel_rect : VkRect2D{});
    if (panel_node) {
      const liquid::LiquidImages panel_images = panel_node->add_to(graph, panel_node->substeps());
      shown = panel_renderer->add_to(graph, panel_images, liquid::HostPanel{shown, panel_rect}).final;
    }
    slot.shot = engine::graph::add_readback(graph, shown, "host.readback");
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
  std::printf("liquid_host: %d frames in %s, %d particles, %d inside the paddle, %u validation message(s)\n", o.frames,
              o.out.string().c_str(), d.active_particles, d.inside_obstacles, context.validation_message_count());
  if (panel_node) {
    const liquid::Diagnostics p = panel_node->diagnose();
    std::printf("liquid_host: the panel's 2D liquid: %d particles, %d outside its walls\n", p.active_particles,
                p.outside_domain);
  }
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
