// The benchmark's reports: the plan and the result tables on the terminal, and the JSON document
// that tools/liquid_benchmark/plot_benchmark.py turns into charts (its keys are that script's input).
#pragma once

#include "tools/liquid_benchmark/plan.h"
#include "tools/liquid_benchmark/run.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tools::benchmark {

// --list: one line per configuration (particles, grid, timed frames, how its scene was changed).
void list_plan(const std::vector<Configuration>& plan);

// The line before a run: how many configurations and frames, at which settings.
void print_plan(const std::vector<Configuration>& plan, const Options& o);

// The tables after a run: wall time, the comparison with the paper (sim+render rows of its
// scenes, when any ran), the viewer's frame rate (when it ran) and the GPU time of each pass.
void print_tables(const std::vector<Result>& results, const Options& o);

// What the JSON records about the run besides its results.
struct RunInfo {
  std::string command_line;
  std::string device_name, driver;
  bool cpu_device = false;
  double wall_time_s = 0.0;
  uint32_t validation_messages = 0;
  std::vector<Skipped> skipped;  // what the plan or the run left out, and why
};

// The whole JSON document: tool, date, command, device, host, settings, the paper's reference,
// one entry per result, wall time and validation messages.
nlohmann::json benchmark_json(const std::vector<Result>& results, const Options& o, const RunInfo& info);

}  // namespace tools::benchmark
