#include "tools/liquid_capture/dry_run.h"

#include "engine/vk/context.h"
#include "liquid/solver/simulation.h"
#include "tools/liquid_capture/frame_writer.h"
#include "tools/liquid_capture/session.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

namespace capture {

namespace fs = std::filesystem;

namespace {

std::string clock_text(double seconds) {
  const long s = long(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return text;
}

// The most steps one probed frame takes: a plan of many steps per frame is timed on this many and
// scaled, so the probe stays a few seconds whatever the plan (and a stop signal is not kept waiting).
constexpr int k_max_probe_steps = 64;
// Frames of each kind timed after the warm-up: the median of three keeps one slow frame (a page
// fault, another process) from setting the estimate.
constexpr int k_probe_frames = 3;

// Wall time of one frame as the run does it, with `steps` steps: GPU work, readbacks, diagnostics
// and, for a written frame, its files (into a scratch folder that is removed again).
double timed_frame(const RunSettings& settings, engine::vk::Context& context, liquid::LiquidNode& node,
                   liquid::LiquidRenderer* renderer, const liquid::CameraView& camera, tools::FrameLoop& loop,
                   const fs::path& scratch, int steps) {
  const auto begin = std::chrono::steady_clock::now();
  const FrameResult result = run_frame(loop, node, renderer, camera, steps, settings.exports_grids());
  const liquid::ParticleSnapshot particles = node.read_particles();
  node.diagnose(particles);
  if (renderer) FrameWriter(settings, context, scratch, node.scene().name).write(1, node, particles, *result.image);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

}  // namespace

void dry_run(const RunSettings& settings, engine::vk::Context& context, liquid::LiquidNode& node,
             liquid::LiquidRenderer& renderer, const liquid::CameraView& camera, tools::FrameLoop& loop,
             std::chrono::steady_clock::time_point process_start) {
  const auto probe_begin = std::chrono::steady_clock::now();
  const FramePlan& plan = settings.plan;
  const liquid::SimulationSetup& s = simulation_of(node).setup();
  std::printf("scene %s (from %s%s):\n%s\n", node.scene().name.c_str(), settings.scene_source.c_str(),
              settings.overrides.empty() ? "" : ", with --set", settings.scene_document.c_str());
  std::printf("setup: %dD, %d particles (capacity %d), grid %dx%dx%d, cell %.4g m, dt %.4g s\n", s.dimension,
              s.initial_particles, s.capacity, s.grid_cells.x, s.grid_cells.y, s.grid_cells.z, s.cell_size,
              plan.time_step);
  std::printf("frames: %d to %d written (%d), %d steps each = %.6g s (%.4g frames/s); frame f is the state at "
              "t = f * %.6g s; simulated from t = 0: %lld steps\n",
              plan.start, plan.end, plan.written(), plan.steps_per_frame, plan.frame_seconds(),
              plan.frames_per_second(), plan.frame_seconds(), (long long)plan.end * plan.steps_per_frame);
  const fs::path& out = settings.folder;
  std::printf("files: %s .. %s", (out / settings.frames.name(plan.start)).c_str(),
              settings.frames.name(plan.end).c_str());
  for (const auto& [pattern, flag] : settings.optional_outputs())
    std::printf(", %s .. %s", pattern->name(plan.start).c_str(), pattern->name(plan.end).c_str());
  std::printf(", stats.csv, summary.json, capture.json");
  if (settings.checkpoint_every > 0) std::printf(", checkpoint.bin every %d frames", settings.checkpoint_every);
  if (!settings.video.empty()) std::printf("; video %s", settings.video.c_str());
  std::printf("\n");

  // The probe: one warm-up frame of each kind (the first use of each graph and its pipelines would
  // otherwise be timed as a frame: it made a late start's estimate 40 % high), then the median of
  // k_probe_frames frames of each kind.
  std::error_code error;
  const fs::path scratch = fs::temp_directory_path() / ("liquid_capture_probe_" + std::to_string(::getpid()));
  fs::create_directories(scratch, error);
  double simulated = 0.0, written = 0.0;
  const int probe_steps = std::min(plan.steps_per_frame, k_max_probe_steps);
  const auto median_frame = [&](liquid::LiquidRenderer* with) {
    std::vector<double> times;
    for (int i = 0; i < k_probe_frames; ++i)
      times.push_back(timed_frame(settings, context, node, with, camera, loop, scratch, probe_steps));
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
  };
  try {
    timed_frame(settings, context, node, &renderer, camera, loop, scratch, probe_steps);
    timed_frame(settings, context, node, nullptr, camera, loop, scratch, probe_steps);
    // A simulated frame is all steps; a written one adds the view and files to the same steps.
    const double probed = median_frame(nullptr);
    simulated = probed * plan.steps_per_frame / probe_steps;
    written = std::max(simulated, median_frame(&renderer) - probed + simulated);
  } catch (...) {
    fs::remove_all(scratch, error);
    throw;
  }
  fs::remove_all(scratch, error);
  const int skipped = plan.start > 0 ? plan.start - 1 : 0;  // frame 0 has no steps
  // What came before the probe (the device, the node's pipelines and uploads) a run does too.
  const double startup = std::chrono::duration<double>(probe_begin - process_start).count();
  const double total = startup + skipped * simulated + plan.written() * written;
  std::printf("estimate: about %s = %.1f s (probe on %s: startup %.1f s, a simulated frame %.0f ms, a written "
              "frame %.0f ms)\n",
              clock_text(total).c_str(), total, context.device_name().c_str(), startup, simulated * 1e3,
              written * 1e3);
}

}  // namespace capture
