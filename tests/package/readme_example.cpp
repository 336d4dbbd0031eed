// The README's engine snippet, verbatim between the markers: compiled with the suite so it stays
// true (tests/package/doc_snippets.py checks that the README still holds exactly this text).
// BEGIN README
#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/io/png.h"
#include "engine/vk/commands.h"
#include "engine/vk/context.h"
#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/scene.h"

int main() {
  engine::vk::Context context;  // or the engine's own; RASTERLIQUIDS_DEVICE picks the device
  liquid::LiquidNode node(context, liquid::load_scene("assets/scenes/dam_break_3d.json"),
                          liquid::LiquidOptions{.frames_in_flight = 1});  // one frame at a time, as below
  liquid::LiquidRenderer renderer(context, node, liquid::RenderSettings{.width = 1024, .height = 768});

  // The scene's camera (or one that frames the domain) ...
  liquid::CameraView camera = liquid::default_camera(node);
  // ... or one of your own, in metres:
  camera = liquid::CameraView{.position = {0.5f, 0.75f, 1.5f}, .target = {0.5f, 0.2f, 0.25f}, .fov_y_degrees = 45.0f};

  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  for (int frame = 0; frame < 16; ++frame) {
    graph.reset();                                                             // forget last frame's passes
    const liquid::LiquidImages images = node.add_to(graph, node.substeps());   // splat -> grid -> particle, per step
    const liquid::RenderOutputs out = renderer.add_to(graph, images, camera);  // raymarch (3D) or 2D view, then FXAA
    // The host's own passes go here, reading out.final, out.depth, images.density, ...
    const engine::graph::Readback shot = engine::graph::add_readback(graph, out.final);
    graph.compile();             // barrier plan; transient images allocated once, reused
    graph.execute(cmd.begin());  // records every pass into the command buffer
    cmd.submit_and_wait();
    engine::vk::write_png("frame.png", shot.rgba8());
  }
}
// END README

// docs/integration.md's live parameters, verbatim.
#include <algorithm>

// A slider's stiffness, held to what the node's present step keeps stable.
void set_stiffness(liquid::LiquidNode& node, float slider_stiffness) {
  liquid::RuntimeParameters p = node.runtime_parameters();
  const liquid::RuntimeParameterRange range = node.runtime_parameter_range(p);
  p.stiffness = std::clamp(slider_stiffness, range.min_stiffness, range.max_stiffness);
  node.set_runtime_parameters(p);
}
