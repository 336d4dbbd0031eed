// liquid_viewer [SCENE]: the liquid in a window, with the mouse's forces and a debug panel.
//   liquid_viewer                          the 3D dam break
//   liquid_viewer assets/scenes/dam_break_2d.json --unthrottled
//   liquid_viewer SCENE --script input.json --frames 60 --screenshot last.png --report state.json --validation
// No display, a bad flag or a bad scene: one line on stderr and a non-zero exit.
#include "tools/common/cli.h"
#include "tools/common/grid_path_flag.h"
#include "tools/liquid_viewer/app.h"
#include "tools/liquid_viewer/script.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

// assets/scenes from the working directory, else from the source tree.
std::filesystem::path scenes_dir() {
  if (std::filesystem::is_directory("assets/scenes")) return "assets/scenes";
  return std::filesystem::path(LIQUID_SOURCE_DIR) / "assets" / "scenes";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Shows a liquid scene in a window: drag with the mouse to push the liquid and move obstacles"};
  viewer::ViewerOptions o;
  std::string scene, script, screenshot, report, pacing = "steps";
  app.add_option("scene", scene, "scene JSON file (default: assets/scenes/dam_break_3d.json)");
  app.add_option("--script", script, "replay timed input events from a JSON file")->check(CLI::ExistingFile);
  app.add_option("--frames", o.frames, "stop after N frames (0: when the window is closed)")
      ->check(tools::integer_range(0, 10000000));
  app.add_option("--screenshot", screenshot, "write the last frame as PNG (needs --frames)");
  app.add_option("--report", report, "write the final state as JSON at exit");
  app.add_option("--width", o.width, "window width")->check(tools::integer_range(64, 8192));
  app.add_option("--height", o.height, "window height")->check(tools::integer_range(64, 8192));
  app.add_option("--steps-per-frame", o.steps_per_frame, "steps per frame in fixed pacing")
      ->check(tools::integer_range(1, 16));
  app.add_option("--pacing", pacing, "steps (fixed steps per frame) or wall (simulated time follows wall time)")
      ->check(CLI::IsMember({"steps", "wall"}));
  app.add_flag("--unthrottled", o.unthrottled, "present with MAILBOX or IMMEDIATE instead of FIFO");
  app.add_flag("--no-panel", [&](int64_t) { o.panel = false; }, "start with the debug panel hidden");
  app.add_flag("--no-overlay", [&](int64_t) { o.overlay = false; },
               "start without the overlay shown while the panel is hidden (O toggles it)");
  app.add_flag("--validation", o.validation, "enable the Vulkan validation layer (any message fails the run)");
  std::string grid_path;
  tools::add_grid_path_option(app, grid_path);
  return tools::run_main(app, argc, argv, "liquid_viewer", [&] {
    o.grid_path = tools::grid_path_from_flag(grid_path);
    o.scenes_dir = scenes_dir();
    o.scene = scene.empty() ? o.scenes_dir / "dam_break_3d.json" : std::filesystem::path(scene);
    o.script = script;
    o.screenshot = screenshot;
    o.report = report;
    o.pacing = pacing == "wall" ? viewer::Pacing::WallTime : viewer::Pacing::FixedSteps;
    if (!o.screenshot.empty() && o.frames == 0) throw std::invalid_argument("--screenshot needs --frames");
    if (!std::filesystem::is_regular_file(o.scene)) throw std::invalid_argument(o.scene.string() + ": no such scene file");
    if (!o.script.empty()) viewer::Script{o.script};  // a bad script is refused before any window opens
    return viewer::run_viewer(o);
  });
}
