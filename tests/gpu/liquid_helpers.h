// Helpers for the liquid GPU tests: load a shipped scene, run a node for some steps on a graph
// (checking validation after every frame), and measure what the physics tests need.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "tests/support/gpu.h"

#include <string>

namespace test {

inline liquid::Scene shipped_scene(const std::string& name) {
  return liquid::load_scene(std::string(LIQUID_ASSET_DIR) + "/scenes/" + name + ".json");
}

// Runs `steps` steps in frames of the scene's substeps; returns the last diagnostics.
inline liquid::Diagnostics run_steps(liquid::LiquidNode& node, int steps) {
  engine::vk::Context& context = gpu();
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  int done = 0;
  while (done < steps) {
    const int n = std::min(node.substeps(), steps - done);
    graph.reset();
    node.add_to(graph, n);
    graph.compile();
    graph.execute(cmd.begin());
    cmd.submit_and_wait();
    done += n;
  }
  return node.diagnose();
}

}  // namespace test
