// liquid_benchmark: times the chapter's configurations headless (simulation only, and simulation
// plus rendering at 1024x768 with FXAA) and 2D scaling runs over particle count and grid size.
// Reports wall time per frame and step, the GPU time of every pass, steps and particles per
// second, beside the paper's Quadro 2000M figures: a table on the terminal and a JSON file that
// tools/liquid_benchmark/plot_benchmark.py turns into charts. plan.h says what runs, run.h how, report.h what is
// written.
#include "tools/common/cli.h"
#include "tools/common/grid_path_flag.h"
#include "tools/liquid_benchmark/plan.h"
#include "tools/liquid_benchmark/report.h"
#include "tools/liquid_benchmark/run.h"

#include "engine/io/atomic_file.h"
#include "engine/vk/context.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#ifndef LIQUID_SOURCE_DIR
#define LIQUID_SOURCE_DIR "."
#endif

namespace {

namespace fs = std::filesystem;
using namespace tools::benchmark;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int run(const Options& o, const std::string& command_line) {
  const auto start = Clock::now();
  const std::vector<Configuration> plan = make_plan(o);
  if (o.list) {
    list_plan(plan);
    return 0;
  }
  // Fail now, not after minutes of measuring, when the JSON cannot be written.
  engine::io::ensure_writable_folder(o.json_path.has_parent_path() ? o.json_path.parent_path() : fs::path("."));
  engine::vk::Context context(engine::vk::ContextOptions{.validation = o.validation});
  std::printf("device: %s; driver: %s; host: %u hardware threads\n", context.device_name().c_str(),
              context.driver_description().c_str(), std::thread::hardware_concurrency());
  print_plan(plan, o);

  std::vector<Result> results;
  for (size_t i = 0; i < plan.size(); ++i) {
    results.push_back(run_configuration(context, plan[i], o));
    const Figures f = figures_of(results.back(), o.steps_per_frame);
    std::printf("[%2zu/%zu] %-34s %9.2f ms/frame  (%5.1f s; %.0f s elapsed)\n", i + 1, plan.size(),
                plan[i].name.c_str(), f.frame.median, results.back().total_s, seconds_since(start));
    std::fflush(stdout);
  }
  print_tables(results, o);

  const RunInfo info{.command_line = command_line,
                     .device_name = context.device_name(),
                     .driver = context.driver_description(),
                     .cpu_device = context.is_cpu_device(),
                     .wall_time_s = seconds_since(start),
                     .validation_messages = context.validation_message_count()};
  engine::io::write_file_atomically(o.json_path, benchmark_json(results, o, info).dump(2) + "\n");
  std::printf("\nwrote %s; total wall time %.1f s\n", o.json_path.string().c_str(), info.wall_time_s);
  if (o.validation) std::printf("validation messages: %u\n", info.validation_messages);
  tools::fail_on_validation_messages(info.validation_messages);
  return 0;
}

fs::path default_scenes_dir() {
  if (fs::is_directory("assets/scenes")) return "assets/scenes";
  return fs::path(LIQUID_SOURCE_DIR) / "assets" / "scenes";
}

std::string join_arguments(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the paper's liquid configurations and 2D scaling runs; writes a table and JSON"};
  Options o;
  o.scenes_dir = default_scenes_dir();
  app.add_option("-o,--json", o.json_path, "JSON output file (its folder is created)");
  app.add_option("--scenes", o.scenes_dir, "folder holding paper_*.json and shallow_water.json")->check(CLI::ExistingDirectory);
  auto* warmup =
      app.add_option("--warmup", o.warmup, "untimed frames before timing")->check(tools::integer_range(0, 1000));
  auto* runs =
      app.add_option("--runs", o.runs, "timed frames per paper configuration")->check(tools::integer_range(1, 100000));
  auto* scaling_runs =
      app.add_option("--scaling-runs", o.scaling_runs, "timed frames per scaling point")
          ->check(tools::integer_range(1, 100000));
  app.add_option("--steps-per-frame", o.steps_per_frame, "solver steps per frame (the paper: 1)")
      ->check(tools::integer_range(1, 1000));
  app.add_option("--width", o.width, "frame width in pixels")->check(tools::integer_range(16, 16384));
  app.add_option("--height", o.height, "frame height in pixels")->check(tools::integer_range(16, 16384));
  app.add_option("--only", o.only, "run only configurations whose name contains this (repeatable; see --list)");
  app.add_flag("--quick", o.quick, "a short run: 1 warm-up and 2 timed frames unless given");
  auto* scaling = app.add_flag("--scaling", o.scaling_only, "run only the scaling set");
  app.add_flag("--no-scaling", o.no_scaling, "skip the scaling set")->excludes(scaling);
  app.add_flag("--list", o.list, "list the configurations (particles, grid, timed frames), run nothing");
  app.add_flag("--validation", o.validation, "enable the Vulkan validation layer (exit 1 on any message)");
  std::vector<std::string> paths_3d;
  app.add_option("--3d-path", paths_3d,
                 "run each 3D configuration on these paths (geometry, vertex-layer, atlas; comma-separated or "
                 "repeated), named .../<path>; default: once, on the device's best")
      ->delimiter(',')
      ->check(tools::grid_path_check());
  return tools::run_main(app, argc, argv, "liquid_benchmark", [&] {
    for (const std::string& name : paths_3d) o.paths_3d.push_back(*liquid::find_grid_path(name));
    if (o.quick) {
      if (warmup->count() == 0) o.warmup = 1;
      if (runs->count() == 0) o.runs = 2;
      if (scaling_runs->count() == 0) o.scaling_runs = 2;
    }
    return run(o, join_arguments(argc, argv));
  });
}
