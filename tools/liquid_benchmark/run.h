// Running one configuration of the plan: warm-up and timed frames through the tools' frame loop,
// the GPU time of every pass, and a check that the simulation is still sound afterwards.
#pragma once

#include "tools/liquid_benchmark/plan.h"

#include "engine/vk/context.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tools::benchmark {

// Median, minimum and maximum of a set of samples.
struct Stats {
  double median = 0.0, min = 0.0, max = 0.0;
};

Stats stats_of(std::vector<double> samples);

// What a run of liquid_viewer reported (the viewer group).
struct ViewerRun {
  std::string binary, display;
  double average_fps = 0.0;  // over the frames after the first
  int frames = 0;
  uint32_t width = 0, height = 0;
  std::string present_mode;
  uint32_t validation_messages = 0;
};

// What one configuration measured.
struct Result {
  const Configuration* config = nullptr;
  int active_particles = 0;
  std::vector<double> frame_ms;                         // wall, per timed frame
  std::vector<std::string> pass_order;                  // as first declared
  std::map<std::string, std::vector<double>> pass_ms;  // GPU, per timed frame, summed over repeats
  std::vector<double> solver_gpu_ms, render_gpu_ms;     // per timed frame
  double setup_s = 0.0, total_s = 0.0;
  // The most device memory the engine's objects held at once while it ran, beyond what was held
  // before: the node's state, its passes' transients, the renderer's targets (Context::memory_peak).
  uint64_t device_memory_bytes = 0;
  std::string grid_path;             // 3D: the path the node ran on; empty in 2D
  std::string stability = "stable";  // else what went wrong
  std::optional<ViewerRun> viewer;   // group "viewer": frame_ms holds the one average frame time
};

// The figures the tables and the JSON report, derived from a result.
struct Figures {
  Stats frame, step, solver_gpu_step, render_gpu;
  double fps = 0.0, steps_per_second = 0.0, particles_per_second = 0.0;
};

Figures figures_of(const Result& r, int steps_per_frame);

// Creates the configuration's node (and renderer for sim+render), runs the options' warm-up
// frames untimed, then the configuration's timed frames; `c` must outlive the result.
Result run_configuration(engine::vk::Context& context, const Configuration& c, const Options& o);

}  // namespace tools::benchmark
