// The frame every tool runs: declare the passes on a fresh graph, compile, record, submit, wait,
// read the GPU timestamps. One place for it, so each tool only says what its frame contains.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "engine/vk/context.h"

#include <chrono>
#include <utility>
#include <vector>

namespace tools {

// What one frame took: the wall time from recording to the fence (one submission run to
// completion; declaring and compiling the graph are CPU work before it, not timed) and the GPU
// time of each pass from the graph's timestamps, in execution order.
struct FrameTime {
  double wall_ms = 0.0;
  std::vector<engine::graph::PassTiming> passes;
};

// A render graph and the command buffer it is recorded into, as a host engine holds them.
class FrameLoop {
 public:
  explicit FrameLoop(engine::vk::Context& context) : graph_(&context), cmd_(context) {}

  // Runs one frame: resets the graph, lets `declare(graph)` add the frame's passes, compiles,
  // executes, submits and waits. Anything `declare` keeps (readbacks) is valid on return.
  template <class Declare>
  FrameTime run(Declare&& declare) {
    graph_.reset();
    std::forward<Declare>(declare)(graph_);
    graph_.compile();
    const auto start = std::chrono::steady_clock::now();
    graph_.execute(cmd_.begin());
    cmd_.submit_and_wait();
    const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return {wall_ms, graph_.read_timings()};
  }

 private:
  engine::graph::RenderGraph graph_;
  engine::vk::CommandBuffer cmd_;
};

}  // namespace tools
