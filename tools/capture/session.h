// What one capture frame runs on the GPU, shared by the run and the dry run's probe: `steps`
// solver steps, then, for a written frame, the view of the state reached and its readback.
#pragma once

#include "engine/graph/transfer.h"
#include "liquid/node.h"
#include "liquid/render/renderer.h"
#include "tools/frame_loop.h"

#include <optional>

namespace capture {

struct FrameResult {
  tools::FrameTime time;
  std::optional<engine::vk::Rgba8Image> image;  // written frames only
};

// `renderer` null: a frame simulated but not written. `fresh_grids`: rebuild the grids from the
// particles after the steps (LiquidNode::add_grids_to), so the view and the exported grids hold
// the frame's own instant; frame 0 (no step yet) needs it to have grids at all.
inline FrameResult run_frame(tools::FrameLoop& loop, liquid::LiquidNode& node, liquid::LiquidRenderer* renderer,
                             const liquid::CameraView& camera, int steps, bool fresh_grids) {
  engine::graph::Readback readback;
  FrameResult result;
  result.time = loop.run([&](engine::graph::RenderGraph& graph) {
    liquid::LiquidImages images = node.add_to(graph, steps);
    if (!renderer) return;
    if (fresh_grids) images = node.add_grids_to(graph, images);
    const liquid::RenderOutputs rendered = renderer->add_to(graph, images, camera);
    readback = engine::graph::add_readback(graph, rendered.final, "capture.readback");
  });
  if (renderer) result.image = readback.rgba8();
  return result;
}

}  // namespace capture
