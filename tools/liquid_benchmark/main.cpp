// liquid_benchmark: times the chapter's configurations headless (simulation only, and simulation
// plus rendering at 1024x768 with FXAA) and 2D scaling runs over particle count and grid size.
// Reports wall time per frame and step, the GPU time of every pass, steps and particles per
// second, beside the paper's Quadro 2000M figures: a table on the terminal and a JSON file that
// tools/liquid_benchmark/plot_benchmark.py turns into charts. plan.h says what runs, run.h how, report.h what is
// written.
#include "tools/common/cli.h"
#include "tools/common/grid_path_flag.h"
#include "tools/liquid_benchmark/compare.h"
#include "tools/liquid_benchmark/plan.h"
#include "tools/liquid_benchmark/process.h"
#include "tools/liquid_benchmark/report.h"
#include "tools/liquid_benchmark/run.h"
#include "tools/liquid_benchmark/viewer_group.h"

#include "engine/io/atomic_file.h"
#include "engine/vk/context.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>
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

// What the comparison flags ask for, besides the plan's options.
struct CompareOptions {
  std::optional<fs::path> save_reference, reference, from;
  std::optional<fs::path> baseline_binary;
  int rounds = 3;
  std::vector<fs::path> old_results, new_results;
};

// The conditions of a live run, for the reference check before any frame is timed.
RunIdentity identity_of(const engine::vk::Context& context, const Options& o) {
  return {.device = context.device_name(),
          .driver = context.driver_description(),
          .steps_per_frame = o.steps_per_frame,
          .frame_width = int(o.width),
          .frame_height = int(o.height),
          .validation = o.validation};
}

// After a run or --from: the reference saved and/or the check against one.
void reference_steps(const RunMedians& run, const CompareOptions& c, const std::optional<RunMedians>& reference,
                     const std::string& command_line) {
  if (c.save_reference) {
    engine::io::write_file_atomically(*c.save_reference, reference_json(run, command_line).dump(2) + "\n");
    std::printf("\nwrote the reference %s (%zu configurations)\n", c.save_reference->string().c_str(),
                run.order.size());
  }
  if (reference) print_reference_check(*reference, run);
}

void check_writable_parent(const fs::path& file) {
  engine::io::ensure_writable_folder(file.has_parent_path() ? file.parent_path() : fs::path("."));
}

std::optional<RunMedians> load_reference(const CompareOptions& c) {
  if (!c.reference) return std::nullopt;
  return read_medians(*c.reference);
}

int run(const Options& o, const CompareOptions& cmp, const std::string& command_line) {
  const auto start = Clock::now();
  const Plan plan = make_plan(o);
  if (o.list) {
    list_plan(plan.configurations);
    for (const Skipped& k : plan.skipped) std::printf("skipped %s: %s\n", k.name.c_str(), k.reason.c_str());
    return 0;
  }
  // Fail now, not after minutes of measuring, when an output cannot be written or the reference
  // cannot be read.
  check_writable_parent(o.json_path);
  if (cmp.save_reference) check_writable_parent(*cmp.save_reference);
  const std::optional<RunMedians> reference = load_reference(cmp);
  engine::vk::Context context(engine::vk::ContextOptions{.validation = o.validation});
  std::printf("device: %s; driver: %s; host: %u hardware threads\n", context.device_name().c_str(),
              context.driver_description().c_str(), std::thread::hardware_concurrency());
  if (reference) require_same_conditions(reference->identity, reference->source, identity_of(context, o), "this run");
  print_plan(plan.configurations, o);
  std::vector<Skipped> skipped = plan.skipped;
  for (const Skipped& k : skipped) std::printf("skipped %s: %s\n", k.name.c_str(), k.reason.c_str());

  std::unique_ptr<ViewerDisplay> display;  // opened for the first viewer configuration
  uint32_t viewer_validation_messages = 0;
  std::vector<Result> results;
  for (size_t i = 0; i < plan.configurations.size(); ++i) {
    const Configuration& c = plan.configurations[i];
    if (c.group == "viewer") {
      if (!display) display = std::make_unique<ViewerDisplay>(o.width, o.height);
      if (!display->display()) {
        std::printf("[%2zu/%zu] %-34s skipped: %s\n", i + 1, plan.configurations.size(), c.name.c_str(),
                    display->what().c_str());
        skipped.push_back({c.name, display->what()});
        continue;
      }
      const fs::path work = (o.json_path.has_parent_path() ? o.json_path.parent_path() : fs::path(".")) / "viewer";
      results.push_back(run_viewer(c, o, *display, work));
      viewer_validation_messages += results.back().viewer->validation_messages;
    } else {
      results.push_back(run_configuration(context, c, o));
    }
    const Figures f = figures_of(results.back(), o.steps_per_frame);
    std::printf("[%2zu/%zu] %-34s %9.2f ms/frame  (%5.1f s; %.0f s elapsed)\n", i + 1, plan.configurations.size(),
                c.name.c_str(), f.frame.median, results.back().total_s, seconds_since(start));
    std::fflush(stdout);
  }
  display.reset();
  print_tables(results, o);

  const RunInfo info{.command_line = command_line,
                     .device_name = context.device_name(),
                     .driver = context.driver_description(),
                     .cpu_device = context.is_cpu_device(),
                     .wall_time_s = seconds_since(start),
                     .validation_messages = context.validation_message_count() + viewer_validation_messages,
                     .skipped = skipped};
  const nlohmann::json document = benchmark_json(results, o, info);
  engine::io::write_file_atomically(o.json_path, document.dump(2) + "\n");
  std::printf("\nwrote %s; total wall time %.1f s\n", o.json_path.string().c_str(), info.wall_time_s);
  if (o.validation) std::printf("validation messages: %u\n", info.validation_messages);
  tools::fail_on_validation_messages(info.validation_messages);
  reference_steps(medians_of_results(document, o.json_path.string()), cmp, reference, command_line);
  return 0;
}

// --from: a saved run's results instead of a new run, for --save-reference and --reference.
int run_from_file(const CompareOptions& cmp, const std::string& command_line) {
  if (!cmp.save_reference && !cmp.reference)
    throw std::invalid_argument("--from " + cmp.from->string() + ": needs --reference or --save-reference");
  if (cmp.save_reference) check_writable_parent(*cmp.save_reference);
  const RunMedians run = read_medians(*cmp.from);
  const std::optional<RunMedians> reference = load_reference(cmp);
  if (reference) require_same_conditions(reference->identity, reference->source, run.identity, run.source);
  reference_steps(run, cmp, reference, command_line);
  return 0;
}

// --old-results/--new-results: the alternating comparison of saved rounds.
int compare_saved(const CompareOptions& cmp) {
  std::vector<RunMedians> old_rounds, new_rounds;
  for (const fs::path& p : cmp.old_results) old_rounds.push_back(read_medians(p));
  for (const fs::path& p : cmp.new_results) new_rounds.push_back(read_medians(p));
  const Comparison c = compare_rounds(old_rounds, new_rounds);
  print_comparison(c, "--old-results", "--new-results");
  return 0;
}

// The arguments the two builds both get in the alternating comparison: this command line without
// the comparison's own flags and the output file, which each round sets.
std::vector<std::string> forwarded_arguments(int argc, char** argv) {
  const std::vector<std::string> dropped = {"--baseline-binary", "--rounds", "-o", "--json"};
  std::vector<std::string> out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    bool drop = false;
    for (const std::string& d : dropped) {
      if (a == d) {
        drop = true;
        ++i;  // and its value
      } else if (a.rfind(d + "=", 0) == 0 || (d == "-o" && a.size() > 2 && a.rfind("-o", 0) == 0)) {
        drop = true;
      }
      if (drop) break;
    }
    if (!drop) out.push_back(a);
  }
  return out;
}

// --baseline-binary: the other build's benchmark and this one, old then new, for --rounds rounds,
// each a process of its own with the same arguments; then the comparison of their medians.
int run_alternating(const Options& o, const CompareOptions& cmp, int argc, char** argv) {
  const auto start = Clock::now();
  const fs::path old_binary = *cmp.baseline_binary;
  if (!fs::is_regular_file(old_binary) || ::access(old_binary.c_str(), X_OK) != 0)
    throw std::invalid_argument("--baseline-binary " + old_binary.string() + ": not an executable file");
  make_plan(o);  // bad options fail here, before any run
  const fs::path folder = o.json_path.has_parent_path() ? o.json_path.parent_path() : fs::path(".");
  const fs::path rounds_folder = folder / "rounds";
  engine::io::ensure_writable_folder(rounds_folder);
  const fs::path new_binary = own_binary();
  const std::vector<std::string> arguments = forwarded_arguments(argc, argv);
  std::string shown;
  for (const std::string& a : arguments) shown += " " + a;
  std::printf("alternating %d round(s), old then new in each, each run with:%s\n  old: %s\n  new: %s\n",
              cmp.rounds, shown.c_str(), old_binary.string().c_str(), new_binary.string().c_str());
  std::vector<RunMedians> old_rounds, new_rounds;
  for (int k = 1; k <= cmp.rounds; ++k) {
    for (const auto& [which, binary] : {std::pair{"old", old_binary}, std::pair{"new", new_binary}}) {
      const fs::path json = rounds_folder / (std::string(which) + "_" + std::to_string(k) + ".json");
      const fs::path log = rounds_folder / (std::string(which) + "_" + std::to_string(k) + ".log");
      std::vector<std::string> command = {binary.string()};
      command.insert(command.end(), arguments.begin(), arguments.end());
      command.insert(command.end(), {"-o", json.string()});
      const auto run_start = Clock::now();
      fs::remove(json);
      const int code = run_process(command, {}, log);
      if (code != 0)
        throw std::runtime_error(std::string("the ") + which + " build failed in round " + std::to_string(k) +
                                 " (exit " + std::to_string(code) + "): " + failure_line(log) + " (its output: " +
                                 log.string() + ")");
      (std::string(which) == "old" ? old_rounds : new_rounds).push_back(read_medians(json));
      std::printf("[round %d/%d] %s: %5.1f s (%.0f s elapsed), %s\n", k, cmp.rounds, which, seconds_since(run_start),
                  seconds_since(start), json.string().c_str());
      std::fflush(stdout);
    }
  }
  const Comparison c = compare_rounds(old_rounds, new_rounds);
  print_comparison(c, old_binary.string(), new_binary.string());
  const fs::path comparison_file = folder / "comparison.json";
  engine::io::write_file_atomically(comparison_file, comparison_json(c, old_binary.string(), new_binary.string()).dump(2) + "\n");
  std::printf("\nwrote %s and the rounds' JSON and output in %s; total wall time %.1f s\n",
              comparison_file.string().c_str(), rounds_folder.string().c_str(), seconds_since(start));
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
  app.add_flag("--whole-grid", o.whole_grid,
               "3D: the grid passes compute every cell, not only each step's active region (the same results; "
               "for timing the region against the whole grid)");
  std::vector<std::string> paths_3d;
  app.add_option("--3d-path", paths_3d,
                 "run each 3D configuration on these paths (geometry, vertex-layer, atlas; comma-separated or "
                 "repeated), named .../<path>; default: once, on the device's best")
      ->delimiter(',')
      ->check(tools::grid_path_check());
  auto* splat_modes =
      app.add_option("--splat-modes", o.splat_modes,
                     "run each paper_* configuration once per splat mode (the scene's \"splat\" key; comma-separated "
                     "or repeated), named paper_2d_64k:<mode>/sim except point_sprite, the chapter's, which keeps the "
                     "plain name; default point_sprite,separable, a mode this build's scenes lack being skipped")
          ->delimiter(',');
  std::string viewer_path;
  app.add_flag("--composite", o.composite,
               "also composite paper_3d into host targets of each colour and depth format (composite/*)");
  auto* viewer = app.add_option("--viewer", viewer_path,
                                "also time liquid_viewer on dam_break_2d and dam_break_3d (configurations viewer/...): "
                                "its frame rate at --width x --height under an Xvfb of its own; no value: the "
                                "liquid_viewer beside this program")
                     ->expected(0, 1);
  app.add_option("--viewer-frames", o.viewer_frames, "frames per viewer run (default 60 in 2D, 20 in 3D; --quick: 5)")
      ->check(tools::integer_range(2, 100000));
  CompareOptions cmp;
  auto* save_reference = app.add_option("--save-reference", cmp.save_reference,
                                        "write this run's medians (frame and each pass, per configuration) with its "
                                        "device and settings to FILE: a reference for --reference");
  auto* reference = app.add_option("--reference", cmp.reference,
                                   "after the run, each measure's ratio to this reference (same device, driver and "
                                   "settings, else refused) and a WARNING for a pass slower than the rest of the run");
  auto* from = app.add_option("--from", cmp.from,
                              "take a saved run's JSON instead of running (with --reference and/or --save-reference)");
  auto* baseline = app.add_option("--baseline-binary", cmp.baseline_binary,
                                  "another build's liquid_benchmark: run it and this one alternately (old, new, ...) "
                                  "with the same arguments, then each measure's new/old ratio per round and a WARNING "
                                  "for any slower beyond the round-to-round noise");
  app.add_option("--rounds", cmp.rounds, "rounds of the alternating comparison (default 3)")
      ->check(tools::integer_range(1, 100))
      ->needs(baseline);
  auto* old_results = app.add_option("--old-results", cmp.old_results,
                                     "compare saved rounds instead of running: the old build's JSON files in round "
                                     "order (comma-separated or repeated; with --new-results)")
                          ->delimiter(',');
  auto* new_results = app.add_option("--new-results", cmp.new_results,
                                     "the new build's JSON files of the same rounds, in the same order")
                          ->delimiter(',');
  old_results->needs(new_results);
  new_results->needs(old_results);
  baseline->excludes(save_reference)->excludes(reference)->excludes(from)->excludes(old_results);
  from->excludes(old_results);
  reference->excludes(old_results);
  save_reference->excludes(old_results);
  return tools::run_main(app, argc, argv, "liquid_benchmark", [&] {
    for (const std::string& name : paths_3d) o.paths_3d.push_back(*liquid::find_grid_path(name));
    o.splat_modes_given = splat_modes->count() > 0;
    if (viewer->count() > 0) o.viewer = viewer_path.empty() ? viewer_beside_benchmark() : fs::path(viewer_path);
    if (o.viewer && !fs::is_regular_file(*o.viewer))
      throw std::invalid_argument("--viewer " + o.viewer->string() + ": no such program");
    if (o.quick) {
      if (warmup->count() == 0) o.warmup = 1;
      if (runs->count() == 0) o.runs = 2;
      if (scaling_runs->count() == 0) o.scaling_runs = 2;
      if (o.viewer_frames == 0) o.viewer_frames = 5;
    }
    if (!cmp.old_results.empty()) return compare_saved(cmp);
    if (cmp.from) return run_from_file(cmp, join_arguments(argc, argv));
    if (cmp.baseline_binary && !o.list) return run_alternating(o, cmp, argc, argv);
    return run(o, cmp, join_arguments(argc, argv));
  });
}
