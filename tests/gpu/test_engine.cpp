// Engine tests on the GPU (lavapipe in CI) with validation and synchronization validation on.
#include "test_shaders.h"
#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/passes/fullscreen.h"
#include "engine/passes/fxaa.h"
#include "engine/vk/buffer.h"
#include "engine/vk/commands.h"
#include "engine/vk/context.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "tests/support/gpu.h"
#include "tests/support/image_compare.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <cstdlib>

using namespace engine;
using graph::Access;
using graph::ImageHandle;

namespace {

constexpr uint32_t k_size = 192;

// Draws the aliased test pattern, then (optionally) FXAA, and reads both back.
struct PatternFrames {
  vk::Rgba8Image pattern;
  vk::Rgba8Image antialiased;
};

PatternFrames render_pattern(vk::Context& context, const std::string& drop_barriers_of = "") {
  vk::GraphicsPipeline pattern_pipeline(context, vk::GraphicsPipelineDesc{
                                                     .name = "pattern",
                                                     .vertex = passes::fullscreen_vertex_shader(),
                                                     .fragment = test_shaders::pattern_frag,
                                                     .color_formats = {VK_FORMAT_R8G8B8A8_UNORM}});
  passes::FxaaPass fxaa(context, VK_FORMAT_R8G8B8A8_UNORM);
  graph::RenderGraph graph(&context);
  ImageHandle scene = graph.create_image("scene", {vk::ImageKind::Image2D, k_size, k_size, 1, VK_FORMAT_R8G8B8A8_UNORM, 0});
  graph.add_pass("pattern", [&](graph::PassBuilder& b) { scene = b.write(scene, Access::ColorAttachmentWrite); },
                 [&](graph::PassContext& ctx) {
                   pattern_pipeline.bind(ctx.cmd, ctx.width, ctx.height);
                   passes::draw_fullscreen(ctx.cmd);
                 });
  const ImageHandle output = fxaa.add_to(graph, scene);
  if (!drop_barriers_of.empty()) graph.debug_drop_barriers_of(drop_barriers_of);
  const graph::Readback pattern_back = graph::add_readback(graph, scene, "readback.pattern");
  const graph::Readback fxaa_back = graph::add_readback(graph, output, "readback.fxaa");
  graph.compile();
  vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  return {pattern_back.rgba8(), fxaa_back.rgba8()};
}

}  // namespace

TEST_CASE("FXAA through the graph matches its golden and smooths the edges", "[gpu][fxaa]") {
  vk::Context& context = test::gpu();
  const PatternFrames frames = render_pattern(context);
  REQUIRE_NO_VALIDATION_MESSAGES();

  // FXAA must change pixels on the edges and leave flat regions alone: a pass-through or a blur
  // both fail here, whatever the golden says.
  size_t edge_pixels = 0, changed_edges = 0, flat_changed = 0;
  const auto& in = frames.pattern.pixels;
  const auto& out = frames.antialiased.pixels;
  for (uint32_t y = 2; y + 2 < k_size; ++y)
    for (uint32_t x = 2; x + 2 < k_size; ++x) {
      const size_t i = (size_t(y) * k_size + x) * 4;
      int contrast = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          contrast = std::max(contrast, std::abs(int(in[(size_t(y + dy) * k_size + x + dx) * 4 + 1]) - int(in[i + 1])));
      const bool changed = std::abs(int(out[i]) - int(in[i])) + std::abs(int(out[i + 1]) - int(in[i + 1])) +
                               std::abs(int(out[i + 2]) - int(in[i + 2])) > 6;
      if (contrast > 64) {
        ++edge_pixels;
        changed_edges += changed;
      } else if (contrast == 0) {
        int wide = 0;  // FXAA's edge search may reach two pixels away
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx)
            wide = std::max(wide, std::abs(int(in[(size_t(y + dy) * k_size + x + dx) * 4 + 1]) - int(in[i + 1])));
        if (wide == 0) flat_changed += changed;
      }
    }
  INFO("edge pixels " << edge_pixels << ", changed " << changed_edges << ", flat pixels changed " << flat_changed);
  REQUIRE(edge_pixels > 200);
  CHECK(double(changed_edges) / double(edge_pixels) > 0.5);
  CHECK(flat_changed == 0);

  const test::CompareResult result =
      test::compare_with_golden(frames.antialiased, "fxaa_pattern", {.channel_threshold = 4, .max_differing_fraction = 0.002});
  INFO(result.message);
  CHECK(result.passed);
}

TEST_CASE("a graph with a barrier removed is caught by synchronization validation", "[gpu][graph]") {
  vk::Context& context = test::gpu();
  REQUIRE_NO_VALIDATION_MESSAGES();
  context.reset_validation_message_count();
  // FXAA's first pass samples the pattern right after it was rendered: without its barrier this is
  // a read-after-write hazard (and a layout mismatch) that the layer must report.
  render_pattern(context, "fxaa.mark");
  const uint32_t messages = context.validation_message_count();
  context.reset_validation_message_count();
  CHECK(messages > 0);
}

TEST_CASE("layered rendering reaches every slice of a 3D image, through a geometry shader or gl_Layer from the "
          "vertex shader",
          "[gpu][graph]") {
  // Each on a device with only the feature it uses, so the validation layer reports the other.
  const bool geometry = GENERATE(true, false);
  INFO((geometry ? "geometry shader" : "vertex shader"));
  vk::Context& context = test::gpu_with({.geometry_shader = geometry, .vertex_layer_output = !geometry});
  vk::GraphicsPipeline pipeline(
      context, vk::GraphicsPipelineDesc{
                   .name = "layer_id",
                   .vertex = geometry ? passes::fullscreen_layered_vertex_shader() : passes::fullscreen_vertex_layer_shader(),
                   .geometry = geometry ? passes::fullscreen_layered_geometry_shader() : std::span<const uint32_t>{},
                   .fragment = test_shaders::layer_id_frag,
                   .color_formats = {VK_FORMAT_R32G32B32A32_SFLOAT}});
  graph::RenderGraph graph(&context);
  const uint32_t w = 8, h = 6, d = 5;
  ImageHandle volume = graph.create_image("volume", {vk::ImageKind::Image3D, w, h, d, VK_FORMAT_R32G32B32A32_SFLOAT, 0});
  graph.add_pass("fill", [&](graph::PassBuilder& b) { volume = b.write(volume, Access::ColorAttachmentWrite); },
                 [&](graph::PassContext& ctx) {
                   pipeline.bind(ctx.cmd, ctx.width, ctx.height);
                   passes::draw_fullscreen(ctx.cmd, ctx.layers);
                 });
  const graph::Readback readback = graph::add_readback(graph, volume);
  graph.compile();
  vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  const auto bytes = readback.bytes();
  const float* texels = reinterpret_cast<const float*>(bytes.data());
  for (uint32_t z = 0; z < d; ++z)
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const float* t = texels + ((size_t(z) * h + y) * w + x) * 4;
        REQUIRE(t[0] == float(x));
        REQUIRE(t[1] == float(y));
        REQUIRE(t[2] == float(z));
      }
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("upload and download round-trip a 3D float image", "[gpu][transfer]") {
  vk::Context& context = test::gpu();
  vk::Image image(context, {vk::ImageKind::Image3D, 4, 3, 2, VK_FORMAT_R32G32B32A32_SFLOAT,
                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
                  "roundtrip");
  std::vector<float> values(4 * 3 * 2 * 4);
  for (size_t i = 0; i < values.size(); ++i) values[i] = float(i) * 0.5f - 3.0f;
  graph::upload_image(context, image, std::as_bytes(std::span(values)));
  const std::vector<std::byte> back = graph::download_image(context, image);
  REQUIRE(back.size() == values.size() * sizeof(float));
  CHECK(std::memcmp(back.data(), values.data(), back.size()) == 0);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("the context counts the device memory its buffers and images hold and the most they held at once",
          "[gpu][context]") {
  vk::Context& context = test::gpu();
  const VkDeviceSize before = context.memory_in_use();
  context.reset_memory_peak();
  REQUIRE(context.memory_peak() == before);
  const VkDeviceSize texels = 64 * 32 * 8, bytes = texels * 16;  // RGBA32F
  VkDeviceSize with_image = 0;
  {
    vk::Image image(context, {vk::ImageKind::Image3D, 64, 32, 8, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT},
                    "counted");
    with_image = context.memory_in_use();
    CHECK(with_image >= before + bytes);
    CHECK(with_image < before + 2 * bytes);  // its own memory, not a pool's worth
    vk::Buffer buffer(context, 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::HostVisible, "counted");
    CHECK(context.memory_in_use() >= with_image + 4096);
    vk::Image moved = std::move(image);  // a move hands the memory over: counted once
    CHECK(context.memory_in_use() >= with_image + 4096);
    CHECK(context.memory_in_use() < with_image + 2 * 4096 + 1024);
  }
  CHECK(context.memory_in_use() == before);
  CHECK(context.memory_peak() >= with_image + 4096);
  context.reset_memory_peak();
  CHECK(context.memory_peak() == before);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a device that cannot be found is reported, not crashed on", "[gpu][context]") {
  CHECK_THROWS_AS(vk::Context(vk::ContextOptions{.device = "no-such-device-name"}), vk::NoDeviceError);
}
