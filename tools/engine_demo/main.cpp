// engine_demo: the engine alone, no liquid. Renders an aliased test pattern, runs the FXAA pass on
// the same render graph and writes both as PNG. A smoke test of a host's Vulkan setup.
#include "demo_shaders.h"
#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/io/png.h"
#include "engine/passes/fullscreen.h"
#include "engine/passes/fxaa.h"
#include "engine/vk/context.h"

#include "tools/common/cli.h"
#include "tools/common/frame_loop.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>

namespace {

int run(const std::filesystem::path& out_dir, uint32_t size, bool validation) {
  using namespace engine;
  std::filesystem::create_directories(out_dir);
  vk::Context context(vk::ContextOptions{.validation = validation});
  vk::GraphicsPipeline pattern(context, vk::GraphicsPipelineDesc{.name = "pattern",
                                                                 .vertex = passes::fullscreen_vertex_shader(),
                                                                 .fragment = demo_shaders::pattern_frag,
                                                                 .color_formats = {VK_FORMAT_R8G8B8A8_UNORM}});
  passes::FxaaPass fxaa(context, VK_FORMAT_R8G8B8A8_UNORM);
  tools::FrameLoop loop(context);
  graph::Readback raw, final_image;
  const tools::FrameTime frame = loop.run([&](graph::RenderGraph& graph) {
    graph::ImageHandle scene =
        graph.create_image("scene", {vk::ImageKind::Image2D, size, size, 1, VK_FORMAT_R8G8B8A8_UNORM, 0});
    graph.add_pass("pattern", [&](graph::PassBuilder& b) { scene = b.write(scene, graph::Access::ColorAttachmentWrite); },
                   [&](graph::PassContext& ctx) {
                     pattern.bind(ctx.cmd, ctx.width, ctx.height);
                     passes::draw_fullscreen(ctx.cmd);
                   });
    const graph::ImageHandle smoothed = fxaa.add_to(graph, scene);
    raw = graph::add_readback(graph, scene, "readback.raw");
    final_image = graph::add_readback(graph, smoothed, "readback.fxaa");
  });
  vk::write_png(out_dir / "pattern.png", raw.rgba8());
  vk::write_png(out_dir / "pattern_fxaa.png", final_image.rgba8());
  std::printf("engine_demo: %s, wrote %s/pattern.png and pattern_fxaa.png\n", context.device_name().c_str(),
              out_dir.string().c_str());
  for (const auto& t : frame.passes) std::printf("  %-16s %8.3f ms\n", t.name.c_str(), t.milliseconds);
  tools::fail_on_validation_messages(context.validation_message_count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders the engine's test pattern and its FXAA pass to PNG"};
  std::filesystem::path out_dir = "frames/engine_demo";
  uint32_t size = 512;
  bool validation = false;
  app.add_option("-o,--out", out_dir, "output folder");
  app.add_option("--size", size, "image size in pixels")->check(tools::integer_range(16, 4096));
  app.add_flag("--validation", validation, "enable the Vulkan validation layer");
  return tools::run_main(app, argc, argv, "engine_demo", [&] { return run(out_dir, size, validation); });
}
