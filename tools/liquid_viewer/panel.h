// The debug panel's contents (Dear ImGui): frame rate, steps, the GPU time of every pass, the
// diagnostics, the live parameters, the brush, pacing, the scene picker and the keys. It changes
// the settings and the node's runtime parameters in place and returns what else it asks for.
// With the panel hidden, a small overlay shows what one needs to know at a glance. Both are
// display only: nothing of the simulation reads what they show.
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

// Where the panel was drawn, window pixels (for the report).
struct PanelRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
  bool collapsed = false;
  // The last error message's text, as laid out (wrapped to the panel's width); 0 without one.
  float message_width = 0.0f, message_height = 0.0f;
};

struct PanelRequest {
  Action action = Action::None;
  std::optional<std::filesystem::path> open_scene;  // picked in the scene list
  PanelRect rect;
};

// The panel's largest share of the window's width.
constexpr float k_panel_max_width_fraction = 0.4f;

// The panel: movable by its title bar (ImGui keeps the place for the session; nothing is saved to
// disk), collapsible, as wide as 26 em but at most 40% of the window, never taller than the
// window (its content scrolls), and kept inside the window when it shrinks.
PanelRequest draw_panel(Settings& settings, MouseTools& mouse, liquid::LiquidNode& node, const Stats& stats,
                        const std::vector<std::filesystem::path>& scenes, const std::filesystem::path& current);

// The overlay shown while the panel is hidden (top left, takes no input): the scene, the frame
// rate, the simulated time, PAUSED when paused, and how to get the panel back. Returns its lines.
std::vector<std::string> draw_overlay(const Settings& settings, const liquid::LiquidNode& node, const Stats& stats,
                                      const std::filesystem::path& current);

}  // namespace viewer
