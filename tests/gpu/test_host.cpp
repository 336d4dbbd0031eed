// The library inside a host engine: a device the host created itself (adopted, not owned), the
// host's own images in the graph (written by the liquid, read back by the host from the state the
// graph reports), depth compositing against the host's depth, and frames in flight.
#include "engine/graph/transfer.h"
#include "engine/vk/buffer.h"
#include "engine/vk/commands.h"
#include "engine/vk/vk_helpers.h"
#include "examples/host/host_vulkan.h"
#include "liquid/renderer.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/gpu/whitewater_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/image_compare.h"

#include <catch2/catch.hpp>
#include <glm/gtc/packing.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <atomic>
#include <cstring>
#include <optional>
#include <memory>

using engine::vk::Image;
using engine::vk::ImageDesc;
using engine::vk::ImageKind;
using engine::vk::ImageSyncState;

namespace {

// A host's flat-shaded octahedron: per face its three corners (counter-clockwise seen from
// outside) with the face's normal, as a vertex buffer for drawing holds them.
std::vector<std::pair<glm::vec3, glm::vec3>> octahedron_corners(float radius) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::pair<glm::vec3, glm::vec3>> corners;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 2; sy < 4; ++sy)
      for (int sz = 4; sz < 6; ++sz) {
        glm::vec3 a = axes[sx], b = axes[sy], c = axes[sz];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0f) std::swap(b, c);
        const glm::vec3 normal = glm::normalize(a + b + c);
        for (const glm::vec3& p : {a, b, c}) corners.emplace_back(p * radius, normal);
      }
  return corners;
}

constexpr uint32_t k_width = 160;
constexpr uint32_t k_height = 120;
constexpr VkImageUsageFlags k_color_usage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags k_depth_usage =
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// The host's background: a colour the liquid's shading never produces.
constexpr std::array<uint8_t, 4> k_magenta{255, 0, 255, 255};

// The host's targets: VkImages with memory of their own (HostImage), wrapped for the graph.
struct HostTargets {
  explicit HostTargets(engine::vk::Context& context, VkFormat color_format = liquid::k_color_format,
                       VkFormat depth_format = liquid::k_depth_format)
      : color_image(context.physical_device(), context.device(), k_width, k_height, color_format, k_color_usage),
        depth_image(context.physical_device(), context.device(), k_width, k_height, depth_format, k_depth_usage),
        color(Image::wrap(context, color_image.image,
                          ImageDesc{ImageKind::Image2D, k_width, k_height, 1, color_format, k_color_usage},
                          "host.color", {})),
        depth(Image::wrap(context, depth_image.image,
                          ImageDesc{ImageKind::Image2D, k_width, k_height, 1, depth_format, k_depth_usage},
                          "host.depth", {})) {}
  HostImage color_image, depth_image;
  Image color, depth;
};

// Barrier from wherever `image` stands to `layout` for transfers.
void to_transfer(VkCommandBuffer cmd, Image& image, VkImageLayout layout, VkAccessFlags2 access, bool keep) {
  const ImageSyncState& s = image.sync_state();
  const VkImageMemoryBarrier2 b = engine::vk::image_barrier(
      image, s.write_stages | s.read_stages, s.write_access, keep ? s.layout : VK_IMAGE_LAYOUT_UNDEFINED,
      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, access, layout);
  engine::vk::cmd_image_barriers(cmd, {&b, 1});
}

// What the host keeps in its stencil (depth formats with one): the liquid must leave it as it was.
constexpr uint8_t k_host_stencil = 0x5a;

// The host's own pass, outside the graph: the colour cleared to magenta, the depth to 1 (the far
// plane), the stencil to k_host_stencil. Leaves both as transfer writes.
void host_clear(VkCommandBuffer cmd, HostTargets& t, float far_depth = 1.0f) {
  to_transfer(cmd, t.color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_2_TRANSFER_WRITE_BIT, false);
  to_transfer(cmd, t.depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_2_TRANSFER_WRITE_BIT, false);
  const VkClearColorValue magenta{{1.0f, 0.0f, 1.0f, 1.0f}};
  const VkImageSubresourceRange color_range = t.color.full_range();
  vkCmdClearColorImage(cmd, t.color.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &magenta, 1, &color_range);
  const VkClearDepthStencilValue far{far_depth, k_host_stencil};
  const VkImageSubresourceRange depth_range = t.depth.full_range();
  vkCmdClearDepthStencilImage(cmd, t.depth.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &depth_range);
  t.color.sync_state() = ImageSyncState::after_write(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                                     VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  t.depth.sync_state() = t.color.sync_state();
}

// Host objects as depth: bands [x0, x1) of every row at depth d, the rest at the far plane
// (uploaded into the host's depth through the graph).
std::vector<float> banded_depth(const std::vector<std::array<float, 3>>& bands, float far_depth) {
  std::vector<float> depth(size_t(k_width) * k_height, far_depth);
  for (const auto& [x0, x1, d] : bands)
    for (uint32_t y = 0; y < k_height; ++y)
      for (uint32_t x = uint32_t(x0); x < uint32_t(x1); ++x) depth[size_t(y) * k_width + x] = d;
  return depth;
}

// The host reads an image back with its own copy, from the layout and access the graph left.
std::vector<std::byte> host_read(engine::vk::Context& context, Image& image, uint32_t texel_bytes,
                                 std::optional<VkImageAspectFlags> aspect = std::nullopt) {
  engine::vk::Buffer buffer(context, VkDeviceSize(k_width) * k_height * texel_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            engine::vk::MemoryUsage::HostVisible, "host.readback");
  engine::vk::CommandBuffer cmd(context);
  VkCommandBuffer c = cmd.begin();
  to_transfer(c, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_2_TRANSFER_READ_BIT, true);
  VkBufferImageCopy region{};
  region.imageSubresource = {aspect.value_or(image.aspect()), 0, 0, 1};
  region.imageExtent = {k_width, k_height, 1};
  vkCmdCopyImageToBuffer(c, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1, &region);
  cmd.submit_and_wait();
  image.sync_state() = ImageSyncState::after_read(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  buffer.invalidate();
  const auto* bytes = static_cast<const std::byte*>(buffer.mapped());
  return {bytes, bytes + buffer.size()};
}

struct Composite {
  engine::vk::Rgba8Image color;  // the raw texels for 4-byte formats
  std::vector<std::byte> color_bytes;
  std::vector<float> depth;     // 0..1, from any depth format
  std::vector<uint8_t> stencil;  // formats with a stencil
  ImageSyncState color_state;  // where the graph left the host's colour
};

// One frame: the host's clear (and depth bands), then the node's steps and the composited
// raymarch into the host's targets, recorded into the same command buffer; the host reads back.
// small_3d's first 14 ms: 30 of the chapter's steps, 4 of the shipped ones.
constexpr int k_composite_steps = 4;

// How the host draws a frame around the liquid.
struct FrameOptions {
  std::vector<std::array<float, 3>> depth_bands;  // host objects as depth (banded_depth)
  float exposure = 1.0f;                          // HDR targets
  std::optional<bool> fxaa = false;
  std::vector<liquid::HostView> views;  // the host's own views, one add_to each; none: the library's camera
  float far_depth = 1.0f;               // the host's depth clear: 0 for reversed Z
  bool whitewater = true;               // RenderSettings::whitewater
};

Composite composite_frame(liquid::LiquidNode& node, HostTargets& targets, int steps, const FrameOptions& o = {},
                          engine::graph::ImageHandle* final_color = nullptr,
                          engine::graph::ImageHandle* imported_color = nullptr) {
  engine::vk::Context& context = node.context();
  liquid::LiquidRenderer renderer(context, node,
                                  {.width = k_width, .height = k_height, .fxaa = o.fxaa, .composite = true,
                                   .exposure = o.exposure, .whitewater = o.whitewater});
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  VkCommandBuffer c = cmd.begin();
  host_clear(c, targets, o.far_depth);
  const engine::graph::ImageHandle color = graph.import_image("host.color", targets.color);
  engine::graph::ImageHandle depth = graph.import_image("host.depth", targets.depth);
  if (!o.depth_bands.empty()) {
    const std::vector<float> values = banded_depth(o.depth_bands, o.far_depth);
    depth = engine::graph::add_upload(graph, depth, std::as_bytes(std::span(values)), "host.depth_bands");
  }
  const liquid::LiquidImages images = node.add_to(graph, steps);
  liquid::RenderOutputs rendered;
  if (o.views.empty()) rendered = renderer.add_to(graph, images, liquid::default_camera(node), {color, depth});
  for (const liquid::HostView& view : o.views)
    rendered = renderer.add_to(graph, images, view, {graph.latest(color), graph.latest(depth)});
  if (final_color) *final_color = rendered.final;
  if (imported_color) *imported_color = color;
  graph.compile();
  graph.execute(c);
  cmd.submit_and_wait();
  Composite out;
  out.color_state = targets.color.sync_state();
  const VkFormat color_format = targets.color.desc().format;
  const std::vector<std::byte> rgba = host_read(context, targets.color, color_format == VK_FORMAT_R16G16B16A16_SFLOAT ? 8 : 4);
  out.color_bytes = rgba;
  out.color = {k_width, k_height, std::vector<uint8_t>(size_t(k_width) * k_height * 4)};
  std::memcpy(out.color.pixels.data(), rgba.data(), std::min(rgba.size(), out.color.pixels.size()));
  // Depth aspects copy out as 4 bytes a texel: a float, or D24's unsigned 24 bits in the low bytes.
  const VkFormat depth_format = targets.depth.desc().format;
  const std::vector<std::byte> d = host_read(context, targets.depth, 4);
  out.depth.resize(size_t(k_width) * k_height);
  std::memcpy(out.depth.data(), d.data(), out.depth.size() * sizeof(float));
  if (depth_format == VK_FORMAT_D24_UNORM_S8_UINT)
    for (size_t i = 0; i < out.depth.size(); ++i) {
      uint32_t bits = 0;
      std::memcpy(&bits, &d[i * 4], 4);
      out.depth[i] = float(bits & 0xffffffu) / float(0xffffffu);
    }
  if (engine::vk::has_stencil(depth_format)) {
    const std::vector<std::byte> st = host_read(context, targets.depth, 1, VK_IMAGE_ASPECT_STENCIL_BIT);
    out.stencil.resize(out.depth.size());
    std::memcpy(out.stencil.data(), st.data(), out.stencil.size());
  }
  return out;
}

bool is_magenta(const engine::vk::Rgba8Image& image, size_t pixel) {
  return std::memcmp(&image.pixels[pixel * 4], k_magenta.data(), 4) == 0;
}

}  // namespace

TEST_CASE("a host's own device is adopted, not owned, and runs the node with zero validation messages", "[host]") {
  HostVulkan host(/*validation=*/true);
  {
    engine::vk::Context context(host.host_device());
    CHECK_FALSE(context.owns_device());
    CHECK(context.device() == host.device);
    CHECK(context.queue_family() == host.queue_family);
    liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
    engine::graph::RenderGraph graph(&context);
    engine::vk::CommandBuffer cmd(context);
    for (int frame = 0; frame < 3; ++frame) {
      test::run_frame(node, graph, cmd, 5);
    }
    const liquid::Diagnostics d = node.diagnose();
    CHECK(d.active_particles == simulation_of(node).setup().initial_particles);
    CHECK(d.non_finite == 0);
    INFO("last validation message: " << context.last_validation_message());
    CHECK(context.validation_message_count() == 0u);
  }
  // The context is gone; the host's device is still the host's to use and destroy.
  CHECK(vkDeviceWaitIdle(host.device) == VK_SUCCESS);
}

TEST_CASE("torn down in the documented order, the library leaves nothing alive on the host's device", "[host]") {
  // The host's messenger outlives its device, so an object left alive is reported at vkDestroyDevice.
  std::atomic<uint32_t> host_messages{0};
  uint32_t library_messages = 0;
  {
    HostVulkan host(/*validation=*/true, &host_messages);
    engine::vk::Context context(host.host_device(), engine::vk::ContextOptions{.print_validation_messages = false});
    {
      HostTargets targets(context);  // the host's images and their wrappers
      liquid::LiquidNode node(context, test::shipped_scene("small_3d"), {.frames_in_flight = 2});
      liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .composite = true});
      engine::graph::RenderGraph graph(&context);
      engine::vk::CommandBuffer cmd(context);
      for (int frame = 0; frame < 2; ++frame) {
        graph.reset();
        VkCommandBuffer c = cmd.begin();
        host_clear(c, targets);
        const liquid::LiquidImages images = node.add_to(graph, 2);
        renderer.add_to(graph, images, liquid::default_camera(node),
                        {graph.import_image("host.color", targets.color), graph.import_image("host.depth", targets.depth)});
        graph.compile();
        graph.execute(c);
        cmd.submit_and_wait();
      }
      CHECK(node.diagnose().non_finite == 0);
      // Destroyed in reverse: command buffer and graph, renderer, node, then the host's images.
    }
    library_messages = context.validation_message_count();
  }  // the context, then the host's device and instance
  CHECK(library_messages == 0u);
  CHECK(host_messages.load() == 0u);

  // The check can fail: a sampler left alive on a host's device is reported when it is destroyed.
  std::atomic<uint32_t> leak_messages{0};
  {
    HostVulkan host(/*validation=*/true, &leak_messages);
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler leaked = VK_NULL_HANDLE;
    REQUIRE(vkCreateSampler(host.device, &info, nullptr, &leaked) == VK_SUCCESS);
  }
  CHECK(leak_messages.load() > 0u);
}

TEST_CASE("options that choose or create a device are refused for a host's device, naming the option", "[host]") {
  HostVulkan host(/*validation=*/false);
  using engine::vk::ContextOptions;
  const std::pair<ContextOptions, const char*> cases[] = {
      {ContextOptions{.validation = true}, "ContextOptions::validation"},
      {ContextOptions{.device = "cpu"}, "ContextOptions::device"},
      {ContextOptions{.device_extensions = {"VK_KHR_swapchain"}}, "ContextOptions::device_extensions"},
      {ContextOptions{.enable_features = [](engine::vk::DeviceFeatures&, const engine::vk::DeviceFeatures&) {}},
       "ContextOptions::enable_features"},
  };
  for (const auto& [options, name] : cases) {
    INFO(name);
    CHECK_THROWS_WITH(engine::vk::Context(host.host_device(), options), Catch::Contains(name));
  }
  // The one that applies: messages counted, not printed.
  engine::vk::Context quiet(host.host_device(), ContextOptions{.print_validation_messages = false});
  CHECK_FALSE(quiet.owns_device());
}

TEST_CASE("a host device without a feature the library needs is refused, naming the feature", "[host]") {
  HostVulkan host(/*validation=*/false);
  // The same physical device, created without large points (which the splat needs).
  engine::vk::DeviceFeatures supported, enabled;
  supported.query(host.physical_device);
  engine::vk::enable_required(enabled, supported);
  enabled.core.features.largePoints = VK_FALSE;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = host.queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  const std::vector<const char*> extensions = engine::vk::required_device_extensions();
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, enabled.chain()};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  REQUIRE(vkCreateDevice(host.physical_device, &info, nullptr, &device) == VK_SUCCESS);
  engine::vk::HostDevice lacking = host.host_device();
  lacking.device = device;
  lacking.enabled_features = enabled.chain();
  CHECK_THROWS_WITH(engine::vk::Context(lacking), Catch::Contains("largePoints"));
  lacking.enabled_device_extensions.clear();
  CHECK_THROWS_WITH(engine::vk::Context(lacking), Catch::Contains("VK_KHR_push_descriptor"));
  vkDestroyDevice(device, nullptr);
}

TEST_CASE("the liquid composites into a host's own images, which the host reads back from the state the graph "
          "reports",
          "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
  HostTargets targets(context);  // host images on the suite's device, with memory of their own
  const Composite frame = composite_frame(node, targets, k_composite_steps, {});
  // The graph left the colour as a colour attachment written by the raymarch.
  CHECK(frame.color_state.layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  CHECK((frame.color_state.write_stages & VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT) != 0);
  size_t liquid = 0, host = 0;
  for (size_t i = 0; i < size_t(k_width) * k_height; ++i) {
    if (is_magenta(frame.color, i)) {
      ++host;
      REQUIRE(frame.depth[i] == 1.0f);  // untouched: the host's own depth
    } else {
      ++liquid;
      REQUIRE(frame.depth[i] < 1.0f);  // the liquid's depth, for the host's later passes
    }
  }
  INFO(liquid << " liquid pixels, " << host << " host pixels");
  CHECK(liquid > size_t(k_width) * k_height / 20);
  CHECK(host > size_t(k_width) * k_height / 4);
  const test::CompareResult golden =
      test::compare_with_golden(frame.color, "host_composite", test::CompareTolerance{12, 0.01});
  INFO(golden.message);
  CHECK(golden.passed);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("FXAA is off by default when compositing, and when on it writes into the host's colour target", "[host]") {
  auto frame = [](std::optional<bool> fxaa, engine::graph::ImageHandle* final_color = nullptr,
                  engine::graph::ImageHandle* imported = nullptr, VkFormat format = liquid::k_color_format) {
    liquid::LiquidNode node(test::gpu(), test::shipped_scene("small_3d"));
    HostTargets targets(test::gpu(), format);
    return composite_frame(node, targets, k_composite_steps, {.fxaa = fxaa}, final_color, imported);
  };
  const Composite off = frame(false);
  const Composite by_default = frame(std::nullopt);
  CHECK(by_default.color.pixels == off.color.pixels);  // off unless asked for
  engine::graph::ImageHandle final_color, imported;
  const Composite on = frame(true, &final_color, &imported);
  CHECK(final_color.id == imported.id);  // the host's own target, not a transient
  size_t changed = 0, liquid_pixels = 0;
  for (size_t p = 0; p < size_t(k_width) * k_height; ++p) {
    if (!is_magenta(off.color, p)) ++liquid_pixels;
    if (std::memcmp(&on.color.pixels[p * 4], &off.color.pixels[p * 4], 4) != 0) ++changed;
  }
  INFO(changed << " pixels smoothed of " << liquid_pixels << " liquid pixels");
  CHECK(changed > 0);                     // edges were smoothed in the host's image
  CHECK(changed < liquid_pixels);         // and only edges
  // The other display-referred formats too, each with a pipeline of its own.
  for (const VkFormat format : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_A2B10G10R10_UNORM_PACK32}) {
    INFO("format " << int(format));
    const Composite plain = frame(false, nullptr, nullptr, format);
    const Composite smoothed = frame(true, nullptr, nullptr, format);
    size_t format_changed = 0;
    for (size_t p = 0; p < size_t(k_width) * k_height; ++p)
      format_changed += std::memcmp(&plain.color.pixels[p * 4], &smoothed.color.pixels[p * 4], 4) != 0;
    INFO(format_changed << " pixels smoothed");
    CHECK(format_changed > 0);
    CHECK(format_changed < liquid_pixels);
  }
  REQUIRE_NO_VALIDATION_MESSAGES();

  // A host colour target that cannot be copied from is refused before anything runs.
  liquid::LiquidNode node(test::gpu(), test::shipped_scene("small_3d"));
  liquid::LiquidRenderer renderer(test::gpu(), node, {.width = k_width, .height = k_height, .fxaa = true, .composite = true});
  engine::graph::RenderGraph graph(&test::gpu());
  const auto import = [&](const char* name, VkFormat format, VkImageUsageFlags usage) {
    return graph.import_image(name, ImageDesc{ImageKind::Image2D, k_width, k_height, 1, format, usage}, {});
  };
  const liquid::HostTargets targets{import("host.color", liquid::k_color_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT),
                                    import("host.depth", liquid::k_depth_format, k_depth_usage)};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 1), liquid::default_camera(node), targets),
                    Catch::Contains("host.color") && Catch::Contains("VK_IMAGE_USAGE_TRANSFER_SRC_BIT"));
  // FXAA before a host's tone map is refused: it is for display-referred colour.
  const liquid::HostTargets hdr{import("host.hdr", VK_FORMAT_R16G16B16A16_SFLOAT, k_color_usage),
                                import("host.depth", liquid::k_depth_format, k_depth_usage)};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 0), liquid::default_camera(node), hdr),
                    Catch::Contains("host.hdr") && Catch::Contains("tone map"));
}

namespace {

// A host's camera: the library's default one, with the host's own projection.
liquid::HostView host_view(const liquid::LiquidNode& node, const glm::mat4& projection, bool reversed_z,
                           VkRect2D viewport = {}) {
  const liquid::CameraView camera = liquid::default_camera(node);
  return {.view = glm::lookAtRH(camera.position, camera.target, camera.up),
          .projection = projection,
          .reversed_z = reversed_z,
          .viewport = viewport};
}

// Vulkan clip space: y down.
glm::mat4 flip_y(glm::mat4 projection) {
  projection[1][1] *= -1.0f;
  return projection;
}

// Reversed Z with an infinite far plane: depth near / -z, 1 at the near plane, 0 at infinity.
glm::mat4 reversed_infinite(float fov_y, float aspect, float near_plane) {
  const float f = 1.0f / std::tan(0.5f * fov_y);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = -f;
  p[2][3] = -1.0f;
  p[3][2] = near_plane;
  return p;
}

size_t differing_pixels(const engine::vk::Rgba8Image& a, const engine::vk::Rgba8Image& b, size_t& liquid) {
  size_t differ = 0;
  liquid = 0;
  for (size_t p = 0; p < size_t(k_width) * k_height; ++p) {
    if (!is_magenta(a, p)) ++liquid;
    for (int c = 0; c < 4; ++c)
      if (std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])) > 8) {
        ++differ;
        break;
      }
  }
  return differ;
}

}  // namespace

TEST_CASE("the host's own view and projection composite the liquid, with forward or reversed Z", "[host]") {
  engine::vk::Context& context = test::gpu();
  auto frame = [&](const FrameOptions& o) {
    liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
    HostTargets targets(context);
    return composite_frame(node, targets, k_composite_steps, o);
  };
  liquid::LiquidNode probe(context, test::shipped_scene("small_3d"));
  const float fov = glm::radians(liquid::default_camera(probe).fov_y_degrees);
  const float aspect = float(k_width) / float(k_height);
  const Composite library = frame({});
  // The host's forward projection, with near and far planes of its own: the same picture.
  const Composite forward =
      frame({.views = {host_view(probe, flip_y(glm::perspectiveRH_ZO(fov, aspect, 0.05f, 40.0f)), false)}});
  size_t liquid = 0;
  const size_t forward_differ = differing_pixels(library.color, forward.color, liquid);
  INFO(forward_differ << " of " << liquid << " liquid pixels differ");
  CHECK(forward_differ <= liquid / 100);
  REQUIRE(liquid > 500);
  // Reversed Z with an infinite far plane: the same picture; the host clears depth to 0.
  const liquid::HostView reversed = host_view(probe, reversed_infinite(fov, aspect, 0.05f), true);
  const Composite open = frame({.views = {reversed}, .far_depth = 0.0f});
  const size_t reversed_differ = differing_pixels(library.color, open.color, liquid);
  INFO(reversed_differ << " of " << liquid << " liquid pixels differ with reversed Z");
  CHECK(reversed_differ <= liquid / 100);
  // The tank placed in the host's world (rotated, moved, scaled) and seen by a camera that moved
  // with it: the same picture, so the placement reaches the march and the depth.
  const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(12.0f, -3.0f, 40.0f)) *
                          glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f))) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(2.5f));
  liquid::HostView placed = reversed;
  placed.model = model;
  placed.view = reversed.view * glm::inverse(model);
  const Composite moved = frame({.views = {placed}, .far_depth = 0.0f});
  const size_t placed_differ = differing_pixels(open.color, moved.color, liquid);
  INFO(placed_differ << " of " << liquid << " liquid pixels differ placed in the world");
  CHECK(placed_differ <= liquid / 100);
  // Host geometry in front (depth 1 is the near plane) hides the left half of the liquid; behind,
  // over its right half, it is covered.
  uint32_t x_min = k_width, x_max = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x)
      if (!is_magenta(open.color, size_t(y) * k_width + x)) x_min = std::min(x_min, x), x_max = std::max(x_max, x);
  const float middle = std::floor(0.5f * float(x_min + x_max));
  const Composite banded = frame({.depth_bands = {{0.0f, middle, 1.0f}, {middle, float(k_width), 1e-6f}},
                                  .views = {reversed},
                                  .far_depth = 0.0f});
  size_t hidden = 0, covered = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const size_t i = size_t(y) * k_width + x;
      if (is_magenta(open.color, i)) continue;
      CHECK(open.depth[i] > 0.0f);  // the liquid's reversed depth, written into the host's
      if (float(x) < middle) {
        CHECK(is_magenta(banded.color, i));
        ++hidden;
      } else {
        CHECK_FALSE(is_magenta(banded.color, i));
        CHECK(banded.depth[i] == open.depth[i]);
        ++covered;
      }
    }
  INFO(hidden << " hidden, " << covered << " covered");
  CHECK(hidden > 50);
  CHECK(covered > 50);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("two views of one step share a target side by side, and an orthographic view draws too", "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode probe(context, test::shipped_scene("small_3d"));
  const float fov = glm::radians(liquid::default_camera(probe).fov_y_degrees);
  const uint32_t half = k_width / 2;
  const glm::mat4 projection = flip_y(glm::perspectiveRH_ZO(fov, float(half) / float(k_height), 0.05f, 40.0f));
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
  HostTargets targets(context);
  const Composite split = composite_frame(
      node, targets, k_composite_steps,
      {.views = {host_view(probe, projection, false, {{0, 0}, {half, k_height}}),
                 host_view(probe, projection, false, {{int32_t(half), 0}, {half, k_height}})}});
  size_t left = 0, right = 0, unequal = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < half; ++x) {
      const size_t l = size_t(y) * k_width + x, r = l + half;
      left += !is_magenta(split.color, l);
      right += !is_magenta(split.color, r);
      unequal += std::memcmp(&split.color.pixels[l * 4], &split.color.pixels[r * 4], 4) != 0;
    }
  INFO(left << " liquid pixels left, " << right << " right, " << unequal << " unequal");
  CHECK(left > 200);
  CHECK(unequal == 0);  // the same view in both halves: the same pixels

  // Orthographic: rays parallel, each from its own point of the near plane.
  const glm::vec3 domain = simulation_of(node).setup().domain;
  const float extent = 0.8f * glm::length(domain);
  liquid::LiquidNode ortho_node(context, test::shipped_scene("small_3d"));
  HostTargets ortho_targets(context);
  const Composite ortho = composite_frame(
      ortho_node, ortho_targets, k_composite_steps,
      {.views = {host_view(probe, flip_y(glm::orthoRH_ZO(-extent, extent, -0.75f * extent, 0.75f * extent, 0.01f, 20.0f)),
                           false)}});
  size_t ortho_liquid = 0;
  for (size_t p = 0; p < size_t(k_width) * k_height; ++p) ortho_liquid += !is_magenta(ortho.color, p);
  CHECK(ortho_liquid > 200);
  REQUIRE_NO_VALIDATION_MESSAGES();

  // A viewport outside the targets is refused before anything runs.
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .composite = true});
  engine::graph::RenderGraph graph(&context);
  const liquid::HostTargets handles{graph.import_image("host.color", targets.color),
                                    graph.import_image("host.depth", targets.depth)};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 0), host_view(probe, projection, false, {{int32_t(half) + 1, 0}, {half, k_height}}),
                                    handles),
                    Catch::Contains("viewport") && Catch::Contains("not inside"));
}

namespace {

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// The linear colour of texel i of a composite read back from a target of `format`.
glm::vec3 linear_texel(const std::vector<std::byte>& bytes, VkFormat format, size_t i) {
  const auto* u8 = reinterpret_cast<const uint8_t*>(bytes.data());
  uint32_t word = 0;
  std::memcpy(&word, u8 + i * 4, 4);
  const auto display = [](glm::vec3 c) { return glm::pow(c, glm::vec3(2.2f)); };
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM: return display(glm::vec3(u8[i * 4], u8[i * 4 + 1], u8[i * 4 + 2]) / 255.0f);
    case VK_FORMAT_B8G8R8A8_UNORM: return display(glm::vec3(u8[i * 4 + 2], u8[i * 4 + 1], u8[i * 4]) / 255.0f);
    case VK_FORMAT_R8G8B8A8_SRGB:
      return {srgb_to_linear(u8[i * 4] / 255.0f), srgb_to_linear(u8[i * 4 + 1] / 255.0f), srgb_to_linear(u8[i * 4 + 2] / 255.0f)};
    case VK_FORMAT_B8G8R8A8_SRGB:
      return {srgb_to_linear(u8[i * 4 + 2] / 255.0f), srgb_to_linear(u8[i * 4 + 1] / 255.0f), srgb_to_linear(u8[i * 4] / 255.0f)};
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
      return display(glm::vec3(word & 1023u, (word >> 10) & 1023u, (word >> 20) & 1023u) / 1023.0f);
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32: return glm::unpackF2x11_1x10(word);
    case VK_FORMAT_R16G16B16A16_SFLOAT: {
      uint16_t h[4];
      std::memcpy(h, u8 + i * 8, 8);
      return {glm::unpackHalf1x16(h[0]), glm::unpackHalf1x16(h[1]), glm::unpackHalf1x16(h[2])};
    }
    default: FAIL("no decoder for format " << int(format)); return {};
  }
}

}  // namespace

TEST_CASE("the liquid composites into the host's colour formats: UNORM, sRGB, 10-bit and HDR float", "[host]") {
  engine::vk::Context& context = test::gpu();
  auto frame = [&](VkFormat format, float exposure = 1.0f) {
    liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
    HostTargets targets(context, format);
    return composite_frame(node, targets, k_composite_steps, {.exposure = exposure});
  };
  const Composite reference = frame(VK_FORMAT_R8G8B8A8_UNORM);
  std::vector<size_t> liquid;
  for (size_t i = 0; i < size_t(k_width) * k_height; ++i)
    if (!is_magenta(reference.color, i)) liquid.push_back(i);
  REQUIRE(liquid.size() > 500);
  // Mean |linear colour - the reference's| over the liquid's pixels, and over the rest (the host's
  // magenta, untouched). The sRGB and float targets blend in linear light, the UNORM reference in
  // display-encoded values, and the liquid is translucent everywhere: measured 0.080 (sRGB), 0.082
  // and 0.079 (float, no shoulder) against 0.0012 for 10-bit UNORM; the bounds are 1.5 times that.
  struct Case {
    VkFormat format;
    double bound;
  };
  double hdr_mean = 0.0;
  for (const Case c : {Case{VK_FORMAT_B8G8R8A8_UNORM, 1e-4}, Case{VK_FORMAT_A2B10G10R10_UNORM_PACK32, 0.01},
                       Case{VK_FORMAT_R8G8B8A8_SRGB, 0.12}, Case{VK_FORMAT_B8G8R8A8_SRGB, 0.12},
                       Case{VK_FORMAT_R16G16B16A16_SFLOAT, 0.12}, Case{VK_FORMAT_B10G11R11_UFLOAT_PACK32, 0.12}}) {
    INFO("format " << int(c.format));
    const Composite f = frame(c.format);
    double difference = 0.0, background = 0.0, mean = 0.0;
    for (size_t i : liquid) {
      const glm::vec3 got = linear_texel(f.color_bytes, c.format, i);
      const glm::vec3 want = linear_texel(reference.color_bytes, VK_FORMAT_R8G8B8A8_UNORM, i);
      difference += double(glm::dot(glm::abs(got - want), glm::vec3(1.0f / 3.0f)));
      mean += double(glm::dot(got, glm::vec3(1.0f / 3.0f)));
    }
    difference /= double(liquid.size());
    mean /= double(liquid.size());
    for (size_t i = 0; i < size_t(k_width) * k_height; i += 7)
      if (is_magenta(reference.color, i))
        background = std::max(background, double(glm::length(linear_texel(f.color_bytes, c.format, i) - glm::vec3(1, 0, 1))));
    INFO("mean linear difference on the liquid " << difference << ", largest off the magenta elsewhere " << background);
    CHECK(difference < c.bound);
    CHECK(background < 0.01);
    if (c.format == VK_FORMAT_R16G16B16A16_SFLOAT) hdr_mean = mean;
  }
  // The exposure scales the liquid's radiance in an HDR target.
  const Composite brighter = frame(VK_FORMAT_R16G16B16A16_SFLOAT, 2.0f);
  double brighter_mean = 0.0;
  for (size_t i : liquid)
    brighter_mean += double(glm::dot(linear_texel(brighter.color_bytes, VK_FORMAT_R16G16B16A16_SFLOAT, i), glm::vec3(1.0f / 3.0f)));
  brighter_mean /= double(liquid.size());
  INFO("HDR mean radiance on the liquid: exposure 1 " << hdr_mean << ", exposure 2 " << brighter_mean);
  // The liquid is mostly transmissive (the host's colour shows through): its own radiance is a
  // small part of the pixel. Measured 0.478 and 0.544.
  CHECK(brighter_mean > hdr_mean + 0.03);
  REQUIRE_NO_VALIDATION_MESSAGES();

  // A format the liquid cannot composite into is refused in one line naming the target.
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .composite = true});
  engine::graph::RenderGraph graph(&context);
  const liquid::HostTargets odd{
      graph.import_image("host.color", ImageDesc{ImageKind::Image2D, k_width, k_height, 1, VK_FORMAT_R32_UINT, k_color_usage}, {}),
      graph.import_image("host.depth", ImageDesc{ImageKind::Image2D, k_width, k_height, 1, liquid::k_depth_format, k_depth_usage}, {})};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 0), liquid::default_camera(node), odd),
                    Catch::Contains("host.color") && Catch::Contains("does not composite into"));
}

TEST_CASE("a composited liquid filters the host's colour per channel with dual-source blending, by one grey "
          "transmittance without it", "[host]") {
  // Over the host's magenta (as much red as blue), water absorbs red first: what shows through it
  // is bluer, channel by channel, where the device blends with two sources.
  auto blue_over_red = [](engine::vk::Context& context, size_t& liquid) {
    liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
    HostTargets targets(context);
    const Composite f = composite_frame(node, targets, k_composite_steps, {});
    double red = 0.0, blue = 0.0;
    liquid = 0;
    for (size_t i = 0; i < size_t(k_width) * k_height; ++i)
      if (!is_magenta(f.color, i)) {
        red += f.color.pixels[i * 4];
        blue += f.color.pixels[i * 4 + 2];
        ++liquid;
      }
    return blue / std::max(red, 1.0);
  };
  engine::vk::Context& context = test::gpu();
  REQUIRE(context.supports_dual_source_blend());  // lavapipe has dualSrcBlend
  size_t tinted_pixels = 0, grey_pixels = 0;
  const double tinted = blue_over_red(context, tinted_pixels);
  engine::vk::ContextOptions options{.validation = true};
  options.enable_features = [](engine::vk::DeviceFeatures& enable, const engine::vk::DeviceFeatures&) {
    enable.core.features.dualSrcBlend = VK_FALSE;
  };
  engine::vk::Context without(options);
  CHECK_FALSE(without.supports_dual_source_blend());
  const double grey = blue_over_red(without, grey_pixels);
  INFO("blue / red over the liquid: " << tinted << " per channel, " << grey << " grey; " << tinted_pixels << " and "
                                      << grey_pixels << " liquid pixels");
  CHECK(tinted_pixels > 500);
  CHECK(grey_pixels == tinted_pixels);  // the same coverage either way
  CHECK(tinted > 1.3 * grey);
  CHECK(without.validation_message_count() == 0u);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("the liquid composites against the host's depth formats and leaves their stencil as it was, and "
          "refuses multisampled targets", "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode probe(context, test::shipped_scene("small_3d"));
  const float fov = glm::radians(liquid::default_camera(probe).fov_y_degrees);
  const float aspect = float(k_width) / float(k_height);
  for (const bool reversed : {false, true}) {
    const liquid::HostView view =
        reversed ? host_view(probe, reversed_infinite(fov, aspect, 0.05f), true)
                 : host_view(probe, flip_y(glm::perspectiveRH_ZO(fov, aspect, 0.05f, 40.0f)), false);
    const float far_depth = reversed ? 0.0f : 1.0f;
    auto frame = [&](VkFormat depth_format, float clear_depth) {
      liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
      HostTargets targets(context, liquid::k_color_format, depth_format);
      return composite_frame(node, targets, k_composite_steps, {.views = {view}, .far_depth = clear_depth});
    };
    const Composite reference = frame(VK_FORMAT_D32_SFLOAT, far_depth);
    size_t liquid = 0;
    for (size_t i = 0; i < size_t(k_width) * k_height; ++i) liquid += !is_magenta(reference.color, i);
    REQUIRE(liquid > 500);
    for (const VkFormat format : {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT}) {
      INFO("depth format " << int(format) << (reversed ? ", reversed Z" : ", forward Z"));
      if (!context.format_supports(format, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
        WARN("the device has no depth attachment of format " << int(format));
        continue;
      }
      const Composite f = frame(format, far_depth);
      size_t differ = 0, stencil_changed = 0;
      float depth_error = 0.0f;
      for (size_t i = 0; i < size_t(k_width) * k_height; ++i) {
        differ += std::memcmp(&f.color.pixels[i * 4], &reference.color.pixels[i * 4], 4) != 0;
        depth_error = std::max(depth_error, std::abs(f.depth[i] - reference.depth[i]));
        stencil_changed += f.stencil[i] != k_host_stencil;
      }
      // The same picture and depth (D24 rounds to 2^-24), and the host's stencil untouched.
      INFO(differ << " pixels differ from D32_SFLOAT's, largest depth difference " << depth_error << ", "
                  << stencil_changed << " stencil values changed");
      CHECK(differ == 0);
      CHECK(depth_error < 1e-6f);
      CHECK(stencil_changed == 0);
      // The depth test is on: host depth at the near plane everywhere hides all the liquid.
      const Composite hidden = frame(format, reversed ? 1.0f : 0.0f);
      size_t shown = 0;
      for (size_t i = 0; i < size_t(k_width) * k_height; ++i) shown += !is_magenta(hidden.color, i);
      CHECK(shown == 0);
    }
  }
  REQUIRE_NO_VALIDATION_MESSAGES();

  // Multisampled targets are refused in one line naming the target: the host resolves first.
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .composite = true});
  engine::graph::RenderGraph graph(&context);
  ImageDesc msaa_color{ImageKind::Image2D, k_width, k_height, 1, liquid::k_color_format, k_color_usage};
  msaa_color.samples = VK_SAMPLE_COUNT_4_BIT;
  const liquid::HostTargets multisampled{
      graph.import_image("host.msaa_color", msaa_color, {}),
      graph.import_image("host.depth", ImageDesc{ImageKind::Image2D, k_width, k_height, 1, liquid::k_depth_format, k_depth_usage}, {})};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 0), liquid::default_camera(node), multisampled),
                    Catch::Contains("host.msaa_color") && Catch::Contains("4 samples") && Catch::Contains("resolved"));
  const liquid::HostTargets odd_depth{
      graph.import_image("host.color", ImageDesc{ImageKind::Image2D, k_width, k_height, 1, liquid::k_color_format, k_color_usage}, {}),
      graph.import_image("host.d16", ImageDesc{ImageKind::Image2D, k_width, k_height, 1, VK_FORMAT_D16_UNORM, k_depth_usage}, {})};
  CHECK_THROWS_WITH(renderer.add_to(graph, node.add_to(graph, 0), liquid::default_camera(node), odd_depth),
                    Catch::Contains("host.d16") && Catch::Contains("does not test against"));
}

TEST_CASE("a node's placement maps world positions, velocities and brushes into the liquid and back, and places "
          "the composite", "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::Scene scene = test::shipped_scene("small_3d");
  liquid::Obstacle ball;
  ball.center = 0.5f * scene.domain;
  ball.radius = 0.1f * scene.domain.y;
  scene.obstacles.push_back(ball);
  liquid::LiquidNode node(context, scene);
  const liquid::Placement placement{.translation = {12.0f, -3.0f, 40.0f},
                                    .rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f))),
                                    .scale = 2.5f};
  node.set_placement(placement);
  const glm::vec3 liquid_point{0.1f, 0.05f, 0.08f}, liquid_velocity{0.3f, -0.2f, 0.1f};
  const glm::vec3 world_point = placement.point_to_world(liquid_point);
  CHECK(glm::length(glm::vec3(placement.world_from_liquid() * glm::vec4(liquid_point, 1.0f)) - world_point) < 1e-4f);
  CHECK(glm::length(placement.point_to_liquid(world_point) - liquid_point) < 1e-5f);

  // An obstacle placed in world coordinates lands in the liquid's frame, and reads back either way.
  node.set_obstacle_pose(0, world_point, placement.vector_to_world(liquid_velocity), liquid::Frame::World);
  const liquid::ObstaclePose in_liquid = node.obstacle_poses(node.time())[0];
  CHECK(glm::length(in_liquid.center - liquid_point) < 1e-5f);
  CHECK(glm::length(in_liquid.velocity - liquid_velocity) < 1e-5f);
  const liquid::ObstaclePose in_world = node.obstacle_poses(node.time(), liquid::Frame::World)[0];
  CHECK(glm::length(in_world.center - world_point) < 1e-4f);
  // A brush in world units: its radius and acceleration scale with the placement.
  node.set_brushes({{.position = world_point, .radius = 0.25f, .acceleration = placement.vector_to_world({0, 5, 0})}},
                   liquid::Frame::World);
  const liquid::ForceBrush brush = simulation_of(node).brushes().at(0);
  CHECK(glm::length(brush.position - liquid_point) < 1e-5f);
  CHECK(brush.radius == Approx(0.1f));
  CHECK(glm::length(brush.acceleration - glm::vec3(0, 5, 0)) < 1e-4f);
  node.set_brushes({});
  // Particles read back in the world are the liquid's, placed.
  const liquid::ParticleSnapshot own = node.read_particles();
  const liquid::ParticleSnapshot world = node.read_particles(liquid::Frame::World);
  REQUIRE(own.positions.size() == world.positions.size());
  float worst = 0.0f;
  for (size_t i = 0; i < own.positions.size(); ++i) {
    worst = std::max(worst, glm::length(glm::vec3(world.positions[i]) - placement.point_to_world(glm::vec3(own.positions[i]))));
    worst = std::max(worst, glm::length(glm::vec3(world.velocities[i]) - placement.vector_to_world(glm::vec3(own.velocities[i]))));
  }
  CHECK(worst < 1e-4f);

  // A placement that is not a rotation, translation and positive uniform scale is refused.
  CHECK_THROWS_WITH(node.set_placement({.scale = 0.0f}), Catch::Contains("scale"));
  CHECK_THROWS_WITH(node.set_placement({.rotation = glm::quat(2.0f, 0.0f, 0.0f, 0.0f)}), Catch::Contains("unit quaternion"));
  CHECK_THROWS_WITH(node.set_placement({.translation = {std::nanf(""), 0.0f, 0.0f}}), Catch::Contains("non-finite"));

  // A HostView without a model draws with the node's placement: the same picture as the model given.
  const glm::mat4 model = placement.world_from_liquid();
  liquid::LiquidNode probe(context, test::shipped_scene("small_3d"));
  const float fov = glm::radians(liquid::default_camera(probe).fov_y_degrees);
  liquid::HostView view = host_view(probe, flip_y(glm::perspectiveRH_ZO(fov, float(k_width) / float(k_height), 0.05f, 400.0f)), false);
  view.view = view.view * glm::inverse(model);
  auto frame = [&](bool placed, std::optional<glm::mat4> view_model) {
    liquid::LiquidNode n(context, test::shipped_scene("small_3d"));
    if (placed) n.set_placement(placement);
    HostTargets targets(context);
    liquid::HostView v = view;
    v.model = view_model;
    return composite_frame(n, targets, k_composite_steps, {.views = {v}});
  };
  const Composite explicit_model = frame(false, model);
  const Composite from_node = frame(true, std::nullopt);
  // The node keeps its rotation normalized, so the two matrices may differ in the last bits.
  size_t liquid = 0;
  const size_t differ = differing_pixels(explicit_model.color, from_node.color, liquid);
  INFO(differ << " of " << liquid << " liquid pixels differ");
  CHECK(liquid > 500);
  CHECK(differ <= liquid / 100);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a host samples the node's density outside the graph, from the state the graph leaves it in", "[host]") {
  engine::vk::Context& context = test::gpu();
  for (const char* name : {"dam_break_2d", "small_3d"}) {
    INFO(name);
    liquid::LiquidNode node(context, test::shipped_scene(name));
    engine::vk::Image& density = node.density_image();
    const ImageDesc& d = density.desc();
    CHECK(d.format == VK_FORMAT_R16_SFLOAT);
    CHECK(density.sampled_view() != VK_NULL_HANDLE);
    engine::vk::Buffer buffer(context, VkDeviceSize(d.width) * d.height * d.depth_or_layers * 2,
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT, engine::vk::MemoryUsage::HostVisible, "host.density");
    for (int frame = 0; frame < 2; ++frame) {
      engine::graph::RenderGraph graph(&context);
      node.add_to(graph, 2);
      graph.compile();
      engine::vk::CommandBuffer cmd(context);
      VkCommandBuffer c = cmd.begin();
      graph.execute(c);
      // The host's own use, in the same command buffer: from where the graph left the density.
      to_transfer(c, density, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_2_TRANSFER_READ_BIT, true);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {d.width, d.height, d.kind == ImageKind::Image3D ? d.depth_or_layers : 1};
      vkCmdCopyImageToBuffer(c, density.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1, &region);
      density.sync_state() = ImageSyncState::after_read(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                                        VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
      cmd.submit_and_wait();
      buffer.invalidate();
      // What the host copied is the node's own read-back of the same state, in the same texel order
      // (a 3D image here: the test device has a geometry-shader path).
      REQUIRE(node.grid_path() != liquid::GridPath::Atlas);
      const std::vector<float> expected = node.read_density_ratio();
      const auto* halves = static_cast<const uint16_t*>(buffer.mapped());
      REQUIRE(expected.size() == size_t(d.width) * d.height * d.depth_or_layers);
      size_t differ = 0;
      double total = 0.0;
      for (size_t i = 0; i < expected.size(); ++i) {
        const float got = glm::unpackHalf1x16(halves[i]);
        differ += got != expected[i];
        total += got;
      }
      CHECK(differ == 0);
      CHECK(total > 1.0);
    }
  }
  // The node's graphs ran after the host's own reads, from the state it recorded: no hazard.
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a 2D liquid composites with alpha into a rectangle of the host's target, with or without its background", "[host]") {
  engine::vk::Context& context = test::gpu();
  const VkRect2D rect{{90, 10}, {64, 48}};
  // The host's target, cleared to magenta, with the panel drawn into its corner.
  liquid::LiquidNode node(context, test::shipped_scene("dam_break_2d"));
  HostTargets targets(context);
  liquid::LiquidRenderer panel_renderer(context, node, {.width = k_width, .height = k_height, .composite = true});
  {
    engine::graph::RenderGraph graph(&context);
    engine::vk::CommandBuffer cmd(context);
    VkCommandBuffer c = cmd.begin();
    host_clear(c, targets);
    const engine::graph::ImageHandle color = graph.import_image("host.color", targets.color);
    const liquid::LiquidImages images = node.add_to(graph, 3);
    const liquid::RenderOutputs out = panel_renderer.add_to(graph, images, liquid::HostPanel{color, rect});
    CHECK(out.final.id == color.id);
    graph.compile();
    graph.execute(c);
    cmd.submit_and_wait();
  }
  const std::vector<std::byte> bytes = host_read(context, targets.color, 4);
  engine::vk::Rgba8Image panel{k_width, k_height, std::vector<uint8_t>(bytes.size())};
  std::memcpy(panel.pixels.data(), bytes.data(), bytes.size());
  // The same state drawn opaque at the rectangle's size, for the liquid's colours.
  liquid::LiquidRenderer opaque_renderer(context, node, {.width = rect.extent.width, .height = rect.extent.height, .fxaa = false});
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  const liquid::RenderOutputs out = opaque_renderer.add_to(graph, node.add_to(graph, 0), liquid::default_camera(node));
  const engine::graph::Readback back = engine::graph::add_readback(graph, out.final);
  graph.compile();
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  const engine::vk::Rgba8Image opaque = back.rgba8();

  const auto in_rect = [&](uint32_t x, uint32_t y) {
    return x >= uint32_t(rect.offset.x) && x < uint32_t(rect.offset.x) + rect.extent.width &&
           y >= uint32_t(rect.offset.y) && y < uint32_t(rect.offset.y) + rect.extent.height;
  };
  size_t outside_changed = 0, inside_liquid = 0, inside_clear = 0, matching = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const size_t i = size_t(y) * k_width + x;
      const bool inside = in_rect(x, y);
      if (!inside) {
        outside_changed += !is_magenta(panel, i);
        continue;
      }
      if (is_magenta(panel, i)) {
        ++inside_clear;
        continue;
      }
      ++inside_liquid;
      // Where the panel shows the liquid fully, its colour is the opaque view's.
      const size_t j = (size_t(y) - rect.offset.y) * rect.extent.width + (x - rect.offset.x);
      bool same = true;
      for (int ch = 0; ch < 3; ++ch) same = same && std::abs(int(panel.pixels[i * 4 + ch]) - int(opaque.pixels[j * 4 + ch])) <= 8;
      matching += same;
    }
  INFO(inside_liquid << " liquid pixels in the panel, " << matching << " as in the opaque view, " << inside_clear
                     << " left to the host, " << outside_changed << " changed outside");
  CHECK(outside_changed == 0);
  CHECK(inside_liquid > 100);
  CHECK(inside_clear > 100);  // no background: the host's pixels show where there is no liquid
  CHECK(matching > inside_liquid * 8 / 10);

  // With the background: the whole rectangle is the opaque view (its letterbox, background and
  // walls too), and still nothing changes outside it.
  {
    engine::graph::RenderGraph with_background(&context);
    engine::vk::CommandBuffer background_cmd(context);
    VkCommandBuffer c = background_cmd.begin();
    host_clear(c, targets);
    panel_renderer.add_to(with_background, node.add_to(with_background, 0),
                          liquid::HostPanel{with_background.import_image("host.color", targets.color), rect, true});
    with_background.compile();
    with_background.execute(c);
    background_cmd.submit_and_wait();
  }
  const std::vector<std::byte> opaque_bytes = host_read(context, targets.color, 4);
  size_t opaque_outside_changed = 0, opaque_inside = 0, opaque_matching = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const size_t i = size_t(y) * k_width + x;
      const bool inside = in_rect(x, y);
      const auto* texel = reinterpret_cast<const uint8_t*>(&opaque_bytes[i * 4]);
      const bool magenta = std::memcmp(texel, k_magenta.data(), 4) == 0;
      if (!inside) {
        opaque_outside_changed += !magenta;
        continue;
      }
      ++opaque_inside;
      const size_t j = (size_t(y) - rect.offset.y) * rect.extent.width + (x - rect.offset.x);
      bool same = !magenta;
      for (int ch = 0; ch < 3; ++ch) same = same && std::abs(int(texel[ch]) - int(opaque.pixels[j * 4 + ch])) <= 8;
      opaque_matching += same;
    }
  INFO(opaque_matching << " of " << opaque_inside << " panel pixels as in the opaque view with the background, "
                       << opaque_outside_changed << " changed outside");
  CHECK(opaque_outside_changed == 0);
  CHECK(opaque_matching > opaque_inside * 95 / 100);
  REQUIRE_NO_VALIDATION_MESSAGES();
  // A rectangle outside the target is refused in one line.
  engine::graph::RenderGraph refused(&context);
  CHECK_THROWS_WITH(panel_renderer.add_to(refused, node.add_to(refused, 0),
                                          liquid::HostPanel{refused.import_image("host.color", targets.color),
                                                            {{120, 0}, {64, 48}}}),
                    Catch::Contains("not inside"));
}

TEST_CASE("host geometry in front of the liquid hides it, host geometry behind it is covered", "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode plain_node(context, test::shipped_scene("small_3d"));
  HostTargets targets(context);
  const Composite open = composite_frame(plain_node, targets, k_composite_steps, {});
  // The same state again, now with a host object in front (depth 0) over the left half of the
  // liquid and one just in front of the far plane (behind the liquid) over its right half.
  uint32_t x_min = k_width, x_max = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x)
      if (!is_magenta(open.color, size_t(y) * k_width + x)) x_min = std::min(x_min, x), x_max = std::max(x_max, x);
  REQUIRE(x_min < x_max);
  const float x_front = 0.5f * float(x_min + x_max), x_behind = x_front;
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"));
  const Composite banded = composite_frame(node, targets, k_composite_steps,
                                           {.depth_bands = {{0.0f, x_front, 0.0f}, {x_behind, float(k_width), 0.99999f}}});
  size_t hidden = 0, covered = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const size_t i = size_t(y) * k_width + x;
      if (is_magenta(open.color, i)) continue;  // no liquid at this pixel
      if (x < uint32_t(x_front)) {
        REQUIRE(is_magenta(banded.color, i));  // the host object in front wins
        REQUIRE(banded.depth[i] == 0.0f);
        ++hidden;
      } else if (x >= uint32_t(x_behind)) {
        REQUIRE_FALSE(is_magenta(banded.color, i));  // the liquid covers the object behind
        REQUIRE(banded.depth[i] < 0.99999f);
        REQUIRE(banded.depth[i] == open.depth[i]);
        ++covered;
      }
    }
  INFO(hidden << " hidden, " << covered << " covered liquid pixels");
  CHECK(hidden > 50);
  CHECK(covered > 50);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("two frames in flight, each with its own graph and command buffer, have no hazards", "[host]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("small_3d"), liquid::LiquidOptions{.frames_in_flight = 2});
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height});
  struct Slot {
    explicit Slot(engine::vk::Context& c) : graph(&c), cmd(c) {}
    engine::graph::RenderGraph graph;
    engine::vk::CommandBuffer cmd;
  };
  std::array<std::unique_ptr<Slot>, 2> slots{std::make_unique<Slot>(context), std::make_unique<Slot>(context)};
  for (int frame = 0; frame < 6; ++frame) {
    Slot& slot = *slots[size_t(frame) % 2];
    VkCommandBuffer cmd = slot.cmd.begin();  // waits for the frame that used this slot two frames ago
    slot.graph.reset();
    const liquid::LiquidImages images = node.add_to(slot.graph, 4);
    renderer.add_to(slot.graph, images, liquid::default_camera(node));
    slot.graph.compile();
    slot.graph.execute(cmd);
    slot.cmd.submit();  // not waited for: the next frame is recorded while this one runs
  }
  for (auto& slot : slots) slot->cmd.wait();
  CHECK(node.diagnose().non_finite == 0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a frame slot reads its own timings while the other frame is still running, and not before its own "
          "finished", "[host][graph]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode light(context, test::shipped_scene("dam_break_2d"));
  // 60k particles: about a second for 40 steps on lavapipe.
  liquid::LiquidNode heavy(context, test::shipped_scene("dam_break_3d"), liquid::LiquidOptions{.max_steps_per_frame = 40});
  engine::graph::RenderGraph graph_a(&context), graph_b(&context);
  engine::vk::CommandBuffer cmd_a(context), cmd_b(context);
  light.add_to(graph_a, 1);
  graph_a.compile();
  graph_a.execute(cmd_a.begin());
  cmd_a.submit_and_wait();
  heavy.add_to(graph_b, 40);
  graph_b.compile();
  graph_b.execute(cmd_b.begin());
  cmd_b.submit();
  // Frame A's timings are there at once; reading them waited for nothing, so B still runs.
  const auto timings = graph_a.read_timings();
  const bool b_running = !cmd_b.finished();
  CHECK(b_running);
  CHECK(!timings.empty());
  for (const auto& t : timings) CHECK(t.milliseconds >= 0.0);
  // B's own, before its fence: a misuse, said so.
  if (b_running) CHECK_THROWS_WITH(graph_b.read_timings(), Catch::Contains("before the frame's submission completed"));
  cmd_b.wait();
  CHECK(!graph_b.read_timings().empty());
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a context the library creates takes a host's extra extensions, features and queue-family test", "[host]") {
  bool asked = false;
  engine::vk::ContextOptions options;
  options.validation = true;
  options.instance_extensions = {VK_KHR_SURFACE_EXTENSION_NAME};
  options.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  options.enable_features = [&](engine::vk::DeviceFeatures& enable, const engine::vk::DeviceFeatures& supported) {
    asked = true;
    enable.core.features.fillModeNonSolid = supported.core.features.fillModeNonSolid;
  };
  {
    engine::vk::Context context(options);
    CHECK(context.owns_device());
    CHECK(asked);
    // The swapchain entry points exist only when VK_KHR_swapchain was enabled on the device.
    CHECK(vkGetDeviceProcAddr(context.device(), "vkCreateSwapchainKHR") != nullptr);
    CHECK(context.validation_message_count() == 0u);
  }
  options.queue_family_filter = [](VkInstance, VkPhysicalDevice, uint32_t) { return false; };
  CHECK_THROWS_WITH(engine::vk::Context(options), Catch::Contains("no graphics queue family the host accepts"));
  options.queue_family_filter = nullptr;
  options.device_extensions = {"VK_NO_such_extension"};
  CHECK_THROWS_WITH(engine::vk::Context(options), Catch::Contains("VK_NO_such_extension"));
}

TEST_CASE("a host's own mesh, from its interleaved vertex buffer, is an obstacle it moves and turns each frame",
          "[gpu][liquid][mesh][host]") {
  engine::vk::Context& context = test::gpu();
  liquid::Scene scene = liquid::parse_scene(R"({ "name": "host mesh", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 3, "domain": [0.3, 0.24, 0.2],
    "grid_resolution": 15, "particle_spacing": 0.01, "stiffness": 9.8, "kernel_radius_cells": 3, "time_step": 0.0004,
    "substeps": 5, "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.3, 0.08, 0.2] } ] })", "host_mesh.json");
  // A host's interleaved vertices: float3 position first, then whatever else (here a float3 normal).
  struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
  };
  std::vector<Vertex> vertices;   // the mesh's own frame, metres
  std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
  for (const auto& [position, normal] : octahedron_corners(0.04f)) {
    indices.push_back(uint32_t(vertices.size()));
    vertices.push_back({position, normal});
  }
  scene.obstacles.push_back(liquid::mesh_obstacle(std::as_bytes(std::span(vertices)), sizeof(Vertex), indices,
                                                  glm::vec3(0.15f, 0.17f, 0.1f), "boat"));
  liquid::LiquidNode node(context, scene);
  const size_t boat = scene.obstacles.size() - 1;
  CHECK(node.scene().obstacles[boat].mesh.vertices.size() == 6);  // the split corners merged
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  for (int frame = 0; frame < 4; ++frame) {
    const glm::vec3 center(0.1f + 0.02f * float(frame), 0.17f, 0.1f);
    const glm::vec3 velocity(0.02f / float(node.substeps() * node.time_step()), 0.0f, 0.0f);
    const glm::quat rotation = glm::angleAxis(0.3f * float(frame), glm::vec3(0.0f, 1.0f, 0.0f));
    // Each frame, before add_to(): where it is, how fast its centre moves, and its own turn and scale.
    node.set_obstacle_pose(boat, center, velocity);
    node.set_mesh_transform(boat, rotation, 1.0f);
    test::run_frame(node, graph, cmd, node.substeps());
  }
  // Moved every step: its field made again every step (resampled, or voxelized if it has no reference).
  CHECK(simulation_of(node).mesh_field()->voxelizations() == 4 * node.substeps());
  // Its surface turns at the rate of the host's turn between the last two frames, for a frame, then stops.
  const double frame_time = node.substeps() * node.time_step();
  CHECK(node.obstacle_poses(node.time())[boat].angular_velocity.y == Approx(0.3 / frame_time).epsilon(1e-3));
  CHECK(node.obstacle_poses(node.time() + 1.01 * frame_time)[boat].angular_velocity.y == 0.0f);
  for (int frame = 4; frame < 5; ++frame) {
    const glm::quat rotation = glm::angleAxis(0.3f * float(frame), glm::vec3(0.0f, 1.0f, 0.0f));
    // Turning at a known rate about the vertical (rad/s, the liquid's frame).
    node.set_mesh_transform(boat, rotation, 1.0f, glm::vec3(0.0f, 2.0f, 0.0f));
    CHECK(node.obstacle_poses(node.time() + 10.0)[boat].angular_velocity.y == 2.0f);  // held until the next call
  }
  CHECK_THROWS_AS(node.set_mesh_transform(boat + 1, glm::quat(1, 0, 0, 0), 1.0f), liquid::ArgumentError);  // no such obstacle
  CHECK_THROWS_AS(node.set_mesh_transform(boat, glm::quat(1, 0, 0, 0), 0.0f), liquid::ArgumentError);
  const liquid::Diagnostics d = node.diagnose();
  CHECK(d.inside_obstacles == 0);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("whitewater is composited over a host's frame and hidden by the host's geometry", "[gpu][host][whitewater]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::whitewater_dam_break());
  test::run_steps(node, test::k_whitewater_impact_steps);
  const auto frame = [&](bool whitewater, std::vector<std::array<float, 3>> bands) {
    HostTargets targets(context);
    return composite_frame(node, targets, 0, {.depth_bands = std::move(bands), .whitewater = whitewater}).color;
  };
  const glm::mat4 vp = liquid::LiquidRenderer(context, node, {.width = k_width, .height = k_height})
                           .view_projection(liquid::default_camera(node));
  const glm::vec3 impact_lo(0.2f, 0.0f, 0.0f), impact_hi = node.scene().domain;
  // Over the host's empty frame, and behind host geometry just past the near plane everywhere.
  const test::BrighterPixels open = test::brighter_pixels(frame(true, {}), frame(false, {}), vp, impact_lo, impact_hi);
  const std::vector<std::array<float, 3>> wall{{0.0f, float(k_width), 1e-6f}};
  const test::BrighterPixels covered = test::brighter_pixels(frame(true, wall), frame(false, wall), vp, impact_lo, impact_hi);
  INFO(open.pixels << " pixels brighter over the host's frame (" << open.in_box << " where the impact is), "
                   << covered.pixels << " behind its geometry");
  CHECK(open.pixels > 50);
  CHECK(open.in_box >= open.pixels * 9 / 10);
  CHECK(covered.pixels == 0);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}
