// The debug panel's contents (Dear ImGui): frame rate, steps, the GPU time of every pass, the
// diagnostics, the live parameters, the brush, pacing, and the scene picker. It changes the
// settings and the node's runtime parameters in place and returns what else it asks for.
#pragma once

#include "engine/graph/render_graph.h"
#include "liquid/types.h"
#include "tools/liquid_viewer/controls.h"
#include "tools/liquid_viewer/input.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace liquid {
class LiquidNode;
}

namespace viewer {

struct Stats {
  double fps = 0.0;
  double frame_ms = 0.0;
  int steps_this_frame = 0;
  double lag = 0.0;  // s behind wall time (wall-time pacing)
  std::vector<engine::graph::PassTiming> passes;  // summed by name over the frame
  std::optional<liquid::Diagnostics> diagnostics;
  std::string simulation_error;  // an unstable state (the viewer pauses)
  std::string scene_error;       // the last reload that failed (the old scene keeps running)
  std::string status;            // e.g. "screenshot written to ..."
  std::string present_mode;
  uint32_t width = 0, height = 0;
};

struct PanelRequest {
  Action action = Action::None;
  std::optional<std::filesystem::path> open_scene;  // picked in the scene list
};

PanelRequest draw_panel(Settings& settings, MouseTools& mouse, liquid::LiquidNode& node, const Stats& stats,
                        const std::vector<std::filesystem::path>& scenes, const std::filesystem::path& current);

}  // namespace viewer
