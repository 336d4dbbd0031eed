// liquid_run: runs a scene headless for N simulation steps or S simulated seconds (no rendering)
// and prints the solver's diagnostics as it goes, then the median GPU time of each pass and the
// wall time per simulated second.
#include "engine/io/atomic_file.h"
#include "engine/vk/context.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "liquid/scene/override.h"

#include "liquid/solver/simulation.h"
#include "tools/common/cli.h"
#include "tools/common/frame_loop.h"
#include "tools/common/grid_path_flag.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <limits>
#include <map>
#include <system_error>
#include <vector>

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The secondary particles by kind, when the scene has them.
void print_whitewater(liquid::Simulation& simulation) {
  if (simulation.whitewater_capacity() == 0) return;
  std::array<int, 4> count{};
  for (const liquid::WhitewaterParticle& p : simulation.read_whitewater()) ++count[size_t(p.kind)];
  std::printf("        whitewater: %d spray, %d foam, %d bubbles (capacity %d)\n", count[1], count[2], count[3],
              simulation.whitewater_capacity());
}

void print_diagnostics(const liquid::Diagnostics& d) {
  std::printf("%7d %9.4f %9d %7d %8d %6d %9.3f %12.5g %12.5g %12.5g %9.3f %10.4g\n", d.step, d.time,
              d.active_particles, d.outside_domain, d.inside_obstacles, d.non_finite, d.max_density_ratio,
              d.kinetic_energy, d.potential_energy, d.mechanical_energy, d.max_speed, d.time_step);
}

// Fails now, not after the whole run, when `path` cannot be written: it is a folder, or its
// folder is missing or read-only. Probes with the temporary file the final write will use.
void check_output_file(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) throw std::runtime_error(path.string() + ": is a directory");
  std::filesystem::path probe = path;
  probe += ".partial";
  {
    std::ofstream file(probe, std::ios::trunc);
    if (!file) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

// The command line's values.
struct RunOptions {
  std::string scene;
  std::vector<std::string> sets;  // --set key=value, applied to the file's document
  int steps = 200;
  double seconds = 0.0;  // > 0: run to this simulated time instead
  int report_every = 50;
  bool validation = false;
  std::string dump_path;
  std::string grid_path;
  bool whole_grid = false;
};

// The scene file, with the --set overrides checked exactly as if the file held them.
liquid::Scene scene_of(const RunOptions& o) {
  if (o.sets.empty()) return liquid::load_scene(o.scene);
  std::vector<liquid::SceneOverride> overrides;
  for (const std::string& text : o.sets) overrides.push_back(liquid::parse_scene_override(text));
  return liquid::parse_scene(liquid::scene_document(o.scene, overrides), o.scene);
}

int run(RunOptions o) {
  const liquid::Scene scene = scene_of(o);
  const std::string& dump_path = o.dump_path;
  const int report_every = o.report_every;
  const double seconds = o.seconds;
  int steps = o.steps;
  if (!dump_path.empty()) check_output_file(dump_path);
  engine::vk::Context context(engine::vk::ContextOptions{.validation = o.validation});
  liquid::LiquidOptions node_options;
  node_options.grid_path = tools::grid_path_from_flag(o.grid_path);
  node_options.active_region = !o.whole_grid;
  node_options.log = tools::stdout_log();
  liquid::LiquidNode node(context, scene, node_options);
  const auto& s = simulation_of(node).setup();
  std::printf("scene %s: %dD, %d particles (capacity %d), grid %dx%dx%d, h = %.4g m, dt = %.3g s%s, k = %.4g, "
              "gamma = %.3g, rho0 = %.5g kg/m^3\n",
              scene.name.c_str(), s.dimension, s.initial_particles, s.capacity, s.grid_cells.x, s.grid_cells.y,
              s.grid_cells.z, s.cell_size, s.time_step, scene.adaptive_time_step ? " (the largest; adaptive)" : "",
              s.stiffness, s.gamma, s.rest_density);
  std::printf("device %s (%s)\n", context.device_name().c_str(), context.driver_description().c_str());
  std::printf("%7s %9s %9s %7s %8s %6s %9s %12s %12s %12s %9s %10s\n", "step", "time_s", "active", "outside",
              "inside_o", "nan", "max_rho", "kinetic_J", "potential_J", "total_J", "max_v", "dt_s");
  print_diagnostics(node.diagnose());

  tools::FrameLoop loop(context);
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<double> step_ms;
  // One submission per batch of at most the scene's substeps, cut so that batches end on every
  // multiple of report_every (the reports fall on the steps asked for). The state is checked after
  // every batch, whatever the report interval: diagnose() throws at the first unstable batch.
  // With --seconds the run ends at that simulated time (the last batch cut to reach it) instead.
  if (seconds > 0.0) steps = std::numeric_limits<int>::max();
  int done = 0;
  auto steps_to_end = [&] {
    if (seconds <= 0.0) return steps - done;
    // In double, clamped before the cast: a long run at a short step needs more than INT_MAX steps.
    const double left = std::ceil((seconds - node.time()) / node.time_step() - 1e-6);
    return int(std::clamp(left, 1.0, double(node.substeps())));
  };
  const auto start = std::chrono::steady_clock::now();
  liquid::Diagnostics last;
  bool last_printed = true;
  while (done < steps && (seconds <= 0.0 || node.time() < seconds - 1e-9)) {
    const int next_report = int(std::min<long long>(steps, (done / report_every + 1LL) * report_every));
    const int n = std::min({node.substeps(), next_report - done, steps_to_end()});
    const tools::FrameTime frame = loop.run([&](engine::graph::RenderGraph& graph) { node.add_to(graph, n); });
    step_ms.push_back(frame.wall_ms / n);
    for (const auto& t : frame.passes) pass_ms[t.name].push_back(t.milliseconds);
    done += n;
    const liquid::Diagnostics d = node.diagnose();
    last_printed = done == next_report;
    if (last_printed) {
      print_diagnostics(d);
      print_whitewater(simulation_of(node));
    }
    last = d;
    node.adapt_time_step(d);  // the scene's adaptive_time_step: the next batch's step from this state
  }
  // Every batch with its diagnosis, as a user's run spends it; setup and pipeline creation excluded.
  const double run_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!last_printed) print_diagnostics(last);
  if (!dump_path.empty()) {
    const auto snapshot = node.read_particles();
    std::string csv = "x,y,z,vx,vy,vz\n";
    char line[192];
    for (size_t i = 0; i < snapshot.positions.size(); ++i) {
      const glm::vec4 &p = snapshot.positions[i], &v = snapshot.velocities[i];
      std::snprintf(line, sizeof line, "%g,%g,%g,%g,%g,%g\n", p.x, p.y, p.z, v.x, v.y, v.z);
      csv += line;
    }
    engine::io::write_file_atomically(dump_path, csv);
  }
  std::printf("median GPU time per pass (ms):");
  for (const auto& [name, values] : pass_ms) std::printf("  %s %.3f", name.c_str(), median(values));
  std::printf("\nmedian wall time per step: %.3f ms\n", median(step_ms));
  std::printf("wall time of the steps: %.3f s for %.5g simulated s in %d steps: %.4g s per simulated second\n",
              run_wall_s, node.time(), done, node.time() > 0.0 ? run_wall_s / node.time() : 0.0);
  tools::fail_on_validation_messages(context.validation_message_count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a liquid scene headless and prints diagnostics and per-pass GPU times"};
  RunOptions o;
  tools::add_grid_path_option(app, o.grid_path);
  app.add_option("--dump-particles", o.dump_path, "write the final particles as CSV");
  app.add_option("scene", o.scene, "scene JSON file")->required();
  app.add_option("--set", o.sets, "override a scene field: key=value, dotted paths (fluid_blocks.0.max=[0.1,0.2])");
  app.add_option("-n,--steps", o.steps, "simulation steps")->check(tools::integer_range(1, 10000000));
  app.add_option("-s,--seconds", o.seconds, "run to this simulated time instead of a step count (s)")
      ->check(tools::finite_range(1e-6, 1e6))
      ->excludes("--steps");
  app.add_option("-r,--report-every", o.report_every, "steps between diagnostics lines (the state is checked every batch)")
      ->check(tools::integer_range(1, 1000000));
  app.add_flag("--validation", o.validation, "enable the Vulkan validation layer");
  app.add_flag("--whole-grid", o.whole_grid,
               "3D: every step's grid passes compute every cell, not only the active region (same results)");
  return tools::run_main(app, argc, argv, "liquid_run", [&] { return run(o); });
}
