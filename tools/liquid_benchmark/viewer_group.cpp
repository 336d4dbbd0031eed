// Running liquid_viewer for the benchmark and reading its report.
#include "tools/liquid_benchmark/viewer_group.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace tools::benchmark {

namespace fs = std::filesystem;

ViewerDisplay::ViewerDisplay(uint32_t width, uint32_t height) {
  if (const auto xvfb = find_on_path("Xvfb")) {
    // A screen larger than the window, so the window keeps its size.
    xvfb_ = std::make_unique<Xvfb>(*xvfb, int(std::max(width + 256, 1280u)), int(std::max(height + 256, 1024u)));
    display_ = xvfb_->display();
    what_ = "Xvfb " + *display_;
    return;
  }
  const char* display = std::getenv("DISPLAY");
  if (display && *display) {
    display_ = display;
    what_ = std::string("$DISPLAY ") + display + " (Xvfb is not installed)";
    return;
  }
  what_ = "no X display ($DISPLAY is not set) and no Xvfb to start one (Debian package xvfb)";
}

fs::path viewer_beside_benchmark() {
  const fs::path beside = own_binary().parent_path() / "liquid_viewer";
  if (!fs::exists(beside))
    throw std::invalid_argument("--viewer: no liquid_viewer beside this benchmark (" + beside.string() +
                                "): build it (target liquid_viewer) or give its path, --viewer PATH");
  return beside;
}

Result run_viewer(const Configuration& c, const Options& o, const ViewerDisplay& display, const fs::path& work) {
  const auto start = std::chrono::steady_clock::now();
  fs::create_directories(work);
  const fs::path report = work / ("viewer_" + c.scene_name + ".json");
  const fs::path log = work / ("viewer_" + c.scene_name + ".log");
  fs::remove(report);
  std::vector<std::string> argv = {o.viewer->string(), c.scene_file.string(),        "--frames",
                                   std::to_string(c.timed_frames), "--width",         std::to_string(o.width),
                                   "--height",  std::to_string(o.height),             "--report",
                                   report.string()};
  if (o.steps_per_frame != 1) argv.insert(argv.end(), {"--steps-per-frame", std::to_string(o.steps_per_frame)});
  if (o.validation) argv.push_back("--validation");
  const int code = run_process(argv, {"DISPLAY=" + *display.display()}, log);
  if (code != 0)
    throw std::runtime_error(c.name + ": liquid_viewer failed (exit " + std::to_string(code) + "): " +
                             failure_line(log) + " (its output: " + log.string() + ")");
  nlohmann::json r;
  try {
    std::ifstream file(report);
    r = nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(c.name + ": " + report.string() + ": the viewer's report is not JSON: " + e.what());
  }
  if (!r.contains("average_fps") || !r["average_fps"].is_number() || r["average_fps"].get<double>() <= 0)
    throw std::runtime_error(c.name + ": " + report.string() + ": no average_fps (it needs 2 frames or more)");

  Result result;
  result.config = &c;
  const double fps = r["average_fps"].get<double>();
  result.frame_ms = {1000.0 / fps};
  result.active_particles = r.value("/diagnostics/active_particles"_json_pointer, 0);
  result.grid_path = r.value("grid_path", "");
  const std::string stability_error = r.value("stability_error", "");
  const std::string simulation_error = r.value("simulation_error", "");
  if (!stability_error.empty() || !simulation_error.empty())
    result.stability = stability_error.empty() ? simulation_error : stability_error;
  result.viewer = ViewerRun{.binary = o.viewer->string(),
                            .display = display.what(),
                            .average_fps = fps,
                            .frames = r.value("frames", 0),
                            .width = r.value("width", 0u),
                            .height = r.value("height", 0u),
                            .present_mode = r.value("present_mode", ""),
                            .validation_messages = r.value("validation_messages", 0u)};
  result.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tools::benchmark
