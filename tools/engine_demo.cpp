// engine_demo: the engine alone, no liquid. Renders an aliased test pattern, runs the FXAA pass on
// the same render graph and writes both as PNG. A smoke test of a host's Vulkan setup.
#include "embedded_shaders.h"
#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/passes/fullscreen.h"
#include "engine/passes/fxaa.h"
#include "engine/vk/commands.h"
#include "engine/vk/context.h"
#include "engine/vk/png.h"

#include "tools/cli.h"

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
                                                                 .fragment = shaders::test_pattern_frag,
                                                                 .color_formats = {VK_FORMAT_R8G8B8A8_UNORM}});
  passes::FxaaPass fxaa(context, VK_FORMAT_R8G8B8A8_UNORM);
  graph::RenderGraph graph(&context);
  graph::ImageHandle scene =
      graph.create_image("scene", {vk::ImageKind::Image2D, size, size, 1, VK_FORMAT_R8G8B8A8_UNORM, 0});
  graph.add_pass("pattern", [&](graph::PassBuilder& b) { scene = b.write(scene, graph::Access::ColorAttachmentWrite); },
                 [&](graph::PassContext& ctx) {
                   pattern.bind(ctx.cmd, ctx.width, ctx.height);
                   passes::draw_fullscreen(ctx.cmd);
                 });
  const graph::ImageHandle smoothed = fxaa.add_to(graph, scene);
  const auto raw = graph::add_readback(graph, scene, "readback.raw");
  const auto final_image = graph::add_readback(graph, smoothed, "readback.fxaa");
  graph.compile();
  vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  vk::write_png(out_dir / "pattern.png", raw.rgba8());
  vk::write_png(out_dir / "pattern_fxaa.png", final_image.rgba8());
  std::printf("engine_demo: %s, wrote %s/pattern.png and pattern_fxaa.png\n", context.device_name().c_str(),
              out_dir.string().c_str());
  for (const auto& t : graph.read_timings()) std::printf("  %-16s %8.3f ms\n", t.name.c_str(), t.milliseconds);
  if (context.validation_message_count() > 0) {
    std::fprintf(stderr, "engine_demo: %u validation message(s)\n", context.validation_message_count());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders the engine's test pattern and its FXAA pass to PNG"};
  std::filesystem::path out_dir = "frames/engine_demo";
  uint32_t size = 512;
  bool validation = false;
  app.add_option("-o,--out", out_dir, "output folder");
  app.add_option("--size", size, "image size in pixels")->check(CLI::Range(16u, 4096u));
  app.add_flag("--validation", validation, "enable the Vulkan validation layer");
  if (const auto exit_code = tools::parse_arguments(app, argc, argv, "engine_demo")) return *exit_code;
  try {
    return run(out_dir, size, validation);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "engine_demo: error: %s\n", error.what());
    return 1;
  }
}
