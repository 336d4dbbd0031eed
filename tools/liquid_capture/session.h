// What one capture frame runs on the GPU, shared by the run and the dry run's probe: `steps`
// solver steps, then, for a written frame, the view of the state reached and its readback.
#pragma once

#include "engine/graph/transfer.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "tools/common/frame_loop.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace capture {

struct FrameResult {
  tools::FrameTime time;
  std::optional<engine::vk::Rgba8Image> image;  // written frames only
};

// `renderer` null: a frame simulated but not written. `fresh_grids`: rebuild the grids from the
// particles after the steps (LiquidNode::add_grids_to), so the view and the exported grids hold
// the frame's own instant; frame 0 (no step yet) needs it to have grids at all.
// Steps past the node's per-frame limit (adaptive steps that shrank) run in graphs of their own
// first, their times added to the frame's.
inline FrameResult run_frame(tools::FrameLoop& loop, liquid::LiquidNode& node, liquid::LiquidRenderer* renderer,
                             const liquid::CameraView& camera, int steps, bool fresh_grids) {
  engine::graph::Readback readback;
  FrameResult result;
  tools::FrameTime earlier;
  while (steps > node.max_steps_per_frame()) {
    const tools::FrameTime t = loop.run([&](engine::graph::RenderGraph& graph) {
      node.add_to(graph, node.max_steps_per_frame());
    });
    earlier.wall_ms += t.wall_ms;
    earlier.passes.insert(earlier.passes.end(), t.passes.begin(), t.passes.end());
    steps -= node.max_steps_per_frame();
  }
  result.time = loop.run([&](engine::graph::RenderGraph& graph) {
    liquid::LiquidImages images = node.add_to(graph, steps);
    if (!renderer) return;
    if (fresh_grids) images = node.add_grids_to(graph, images);
    const liquid::RenderOutputs rendered = renderer->add_to(graph, images, camera);
    readback = engine::graph::add_readback(graph, rendered.final, "capture.readback");
  });
  if (renderer) result.image = readback.rgba8();
  result.time.wall_ms += earlier.wall_ms;
  result.time.passes.insert(result.time.passes.end(), earlier.passes.begin(), earlier.passes.end());
  return result;
}

// The steps of the next frame, which lasts plan.frame_seconds(): the plan's, or with the scene's
// adaptive_time_step as many as the node's CFL step (adapt_time_step() after the last diagnosis)
// needs, each set to the frame's length over their count so every frame falls on its time.
inline int steps_for_frame(liquid::LiquidNode& node, int plan_steps, double frame_seconds) {
  if (!node.scene().adaptive_time_step) return plan_steps;
  const int n = std::max(plan_steps, int(std::ceil(frame_seconds / node.time_step() * (1.0 - 1e-9))));
  node.set_time_step(frame_seconds / n);
  return n;
}

}  // namespace capture
