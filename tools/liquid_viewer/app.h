// The viewer: a window, a swapchain, two frames in flight, the running scene and the panel. Each
// frame: input (the window's and the script's), the node's steps, the liquid renderer and FXAA,
// the present pass into the swapchain image (RGBA8 -> the swapchain's format), the panel, present.
#pragma once

#include "liquid/solver/grid_layout.h"
#include "tools/liquid_viewer/controls.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

namespace viewer {

struct ViewerOptions {
  std::filesystem::path scene;
  std::filesystem::path scenes_dir;  // the picker's folder
  std::filesystem::path script;      // replayed input
  std::filesystem::path screenshot;  // PNG of the last frame
  std::filesystem::path report;      // JSON of the final state
  int frames = 0;                    // 0: until the window is closed
  uint32_t width = 1024, height = 768;
  bool validation = false;
  bool unthrottled = false;  // MAILBOX or IMMEDIATE instead of FIFO
  bool panel = true;
  bool overlay = true;       // the overlay while the panel is hidden
  Pacing pacing = Pacing::FixedSteps;
  int steps_per_frame = 1;
  std::optional<liquid::GridPath> grid_path;  // --3d-path; empty: LIQUID_3D_PATH or the device's best
};

class Viewer;

// Runs the viewer; returns the exit code (non-zero when validation reported anything).
int run_viewer(const ViewerOptions& options);

}  // namespace viewer
