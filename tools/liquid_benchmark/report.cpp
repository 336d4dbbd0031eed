// The terminal tables and the JSON document of a benchmark run.
#include "tools/liquid_benchmark/report.h"

#include "tools/liquid_benchmark/compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <thread>

namespace tools::benchmark {

using nlohmann::json;

void list_plan(const std::vector<Configuration>& plan) {
  for (const Configuration& c : plan)
    std::printf("%-34s %8d particles, grid %-10s %4d timed frames%s%s\n", c.name.c_str(), c.particles,
                grid_label(c.grid).c_str(), c.timed_frames, c.note.empty() ? "" : "  -- ", c.note.c_str());
}

void print_plan(const std::vector<Configuration>& plan, const Options& o) {
  std::printf("%zu configuration(s); %d warm-up frame(s) (not timed) then %d timed frame(s) each (%d per scaling "
              "point); %d step(s) per frame; frames %ux%u with FXAA; 3D grid passes over %s\n",
              plan.size(), o.warmup, o.runs, o.scaling_runs, o.steps_per_frame, o.width, o.height,
              o.whole_grid ? "the whole grid (--whole-grid)" : "each step's active region");
}

namespace {

void print_wall_table(const std::vector<Result>& results, const Options& o) {
  std::printf("\nWall time (recording to fence, one submission per frame, %d step(s) per frame)\n", o.steps_per_frame);
  std::printf("%-34s %8s %10s %12s | %8s %8s %8s | %8s %8s %8s | %8s %9s %7s %8s %s\n", "configuration",
              "particles", "grid", "3D path", "frame ms", "min", "max", "step ms", "min", "max", "steps/s", "Mpart/s",
              "fps", "MiB", "");
  for (const Result& r : results) {
    const Figures f = figures_of(r, o.steps_per_frame);
    std::printf("%-34s %8d %10s %12s | %8.2f %8.2f %8.2f | %8.2f %8.2f %8.2f | %8.2f %9.3f %7.2f %8.1f %s\n",
                r.config->name.c_str(), r.active_particles, grid_label(r.config->grid).c_str(),
                r.grid_path.empty() ? "-" : r.grid_path.c_str(), f.frame.median,
                f.frame.min, f.frame.max, f.step.median, f.step.min, f.step.max, f.steps_per_second,
                f.particles_per_second * 1e-6, f.fps, double(r.device_memory_bytes) / (1 << 20),
                r.stability == "stable" ? "" : "UNSTABLE");
  }
}

void print_paper_table(const std::vector<Result>& results, const Options& o) {
  bool any = false;
  for (const Result& r : results) any = any || r.config->paper.has_value();
  if (!any) return;
  std::printf("\nSimulation + rendering against the paper (%s; fps = frames per second, one step per frame)\n",
              k_paper_device);
  if (o.steps_per_frame != 1)
    std::printf("note: this run took %d steps per frame, so its fps do not compare with the paper's\n",
                o.steps_per_frame);
  std::printf("%-34s %9s %9s | %9s %9s | %9s %9s | %10s\n", "configuration", "ours fps", "ours ms", "paper fps",
              "paper ms", "SPH fps", "SPH ms", "ours/paper");
  for (const Result& r : results) {
    if (!r.config->paper) continue;
    const Figures f = figures_of(r, o.steps_per_frame);
    const PaperFigure& p = *r.config->paper;
    const std::string sph_fps = p.sph_fps > 0 ? std::to_string(int(p.sph_fps)) : "-";
    char sph_ms[32] = "-";
    if (p.sph_fps > 0) std::snprintf(sph_ms, sizeof sph_ms, "%.2f", 1000.0 / p.sph_fps);
    std::printf("%-34s %9.2f %9.2f | %9.0f %9.2f | %9s %9s | %10.4f\n", r.config->name.c_str(), f.fps,
                f.frame.median, p.fps, 1000.0 / p.fps, sph_fps.c_str(), sph_ms, f.fps / p.fps);
  }
}

// Pass columns in pipeline order: the solver's three passes, then the views, then FXAA.
std::vector<std::string> pass_columns(const std::vector<Result>& results) {
  const std::vector<std::string>& order = pipeline_order();
  std::vector<std::string> seen;
  for (const Result& r : results)
    for (const std::string& name : r.pass_order)
      if (std::find(seen.begin(), seen.end(), name) == seen.end()) seen.push_back(name);
  std::vector<std::string> columns;
  for (const std::string& name : order)
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) columns.push_back(name);
  for (const std::string& name : seen)  // passes this tool does not know yet, at the end
    if (std::find(order.begin(), order.end(), name) == order.end()) columns.push_back(name);
  return columns;
}

void print_pass_table(const std::vector<Result>& results) {
  const std::vector<std::string> columns = pass_columns(results);
  std::printf("\nGPU time per pass (median ms per frame, from the graph's timestamps)\n%-34s", "configuration");
  for (const std::string& name : columns) std::printf(" %12s", short_pass_name(name).c_str());
  std::printf(" %12s\n", "sum");
  for (const Result& r : results) {
    if (r.pass_ms.empty()) continue;  // the viewer's rows: frame rate only
    std::printf("%-34s", r.config->name.c_str());
    double sum = 0.0;
    for (const std::string& name : columns) {
      const auto it = r.pass_ms.find(name);
      if (it == r.pass_ms.end()) {
        std::printf(" %12s", "-");
        continue;
      }
      const double ms = stats_of(it->second).median;
      sum += ms;
      std::printf(" %12.3f", ms);
    }
    std::printf(" %12.3f\n", sum);
  }
}

void print_viewer_table(const std::vector<Result>& results) {
  bool any = false;
  for (const Result& r : results) any = any || r.viewer.has_value();
  if (!any) return;
  std::printf("\nliquid_viewer's frame rate (the window, panel shown, one step per frame by default; over the frames "
              "after the first)\n");
  std::printf("%-34s %8s %9s %7s %10s %12s  %s\n", "configuration", "fps", "ms/frame", "frames", "window",
              "present", "display");
  for (const Result& r : results) {
    if (!r.viewer) continue;
    const ViewerRun& v = *r.viewer;
    const std::string window = std::to_string(v.width) + "x" + std::to_string(v.height);
    std::printf("%-34s %8.2f %9.1f %7d %10s %12s  %s%s\n", r.config->name.c_str(), v.average_fps,
                1000.0 / v.average_fps, v.frames, window.c_str(), v.present_mode.c_str(), v.display.c_str(),
                r.stability == "stable" ? "" : "  UNSTABLE");
  }
}

json stats_json(const Stats& s) { return {{"median", s.median}, {"min", s.min}, {"max", s.max}}; }

json result_json(const Result& r, const Options& o) {
  const Configuration& c = *r.config;
  const Figures f = figures_of(r, o.steps_per_frame);
  json passes = json::object();
  for (const std::string& name : r.pass_order) passes[name] = stats_json(stats_of(r.pass_ms.at(name)));
  json j = {{"name", c.name},
            {"group", c.group},
            {"scene", c.scene_name},
            {"mode", mode_name(c.mode)},
            {"view", view_name(c)},
            {"fxaa", c.mode == Mode::SimulationAndRender},
            {"dimension", c.scene.dimension},
            {"grid", {c.grid.x, c.grid.y, c.grid.z}},
            {"particles", r.active_particles},
            {"particle_spacing_m", c.scene.particle_spacing},
            {"grid_path", r.grid_path.empty() ? json(nullptr) : json(r.grid_path)},
            {"steps_per_frame", o.steps_per_frame},
            {"warmup_frames", o.warmup},
            {"timed_frames", c.timed_frames},
            {"frame_wall_ms", stats_json(f.frame)},
            {"step_wall_ms", stats_json(f.step)},
            {"solver_gpu_ms_per_step", stats_json(f.solver_gpu_step)},
            {"render_gpu_ms_per_frame", stats_json(f.render_gpu)},
            {"fps", f.fps},
            {"steps_per_second", f.steps_per_second},
            {"particles_per_second", f.particles_per_second},
            {"gpu_ms_per_frame", passes},
            {"pass_order", r.pass_order},
            {"frame_wall_ms_samples", r.frame_ms},
            {"setup_s", r.setup_s},
            {"device_memory_bytes", r.device_memory_bytes},
            {"stability", r.stability},
            {"note", c.note},
            {"splat", c.splat_mode.empty() ? json(nullptr) : json(c.splat_mode)}};
  if (r.viewer)
    j["viewer"] = {{"binary", r.viewer->binary},         {"display", r.viewer->display},
                   {"average_fps", r.viewer->average_fps}, {"frames", r.viewer->frames},
                   {"width", r.viewer->width},             {"height", r.viewer->height},
                   {"present_mode", r.viewer->present_mode},
                   {"measure", "liquid_viewer --frames N --report: frames per second over the frames after the first"}};
  if (c.paper)
    j["paper"] = {{"fps", c.paper->fps},
                  {"frame_ms", 1000.0 / c.paper->fps},
                  {"sph_fps", c.paper->sph_fps > 0 ? json(c.paper->sph_fps) : json(nullptr)},
                  {"sph_frame_ms", c.paper->sph_fps > 0 ? json(1000.0 / c.paper->sph_fps) : json(nullptr)},
                  {"what", c.paper->what},
                  {"ours_over_paper", f.fps / c.paper->fps}};
  else
    j["paper"] = nullptr;
  return j;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

}  // namespace

void print_tables(const std::vector<Result>& results, const Options& o) {
  print_wall_table(results, o);
  print_paper_table(results, o);
  print_viewer_table(results);
  print_pass_table(results);
}

json benchmark_json(const std::vector<Result>& results, const Options& o, const RunInfo& info) {
  const char* lp_threads = std::getenv("LP_NUM_THREADS");
  json document = {
      {"tool", "liquid_benchmark"},
      {"kind", "results"},
      {"date", utc_now()},
      {"command", info.command_line},
      {"device", {{"name", info.device_name}, {"driver", info.driver}, {"cpu_device", info.cpu_device}}},
      {"host", {{"hardware_threads", std::thread::hardware_concurrency()},
                {"LP_NUM_THREADS", lp_threads ? json(lp_threads) : json(nullptr)}}},
      {"settings", {{"warmup_frames", o.warmup}, {"timed_frames", o.runs}, {"scaling_timed_frames", o.scaling_runs},
                    {"steps_per_frame", o.steps_per_frame}, {"frame_width", o.width}, {"frame_height", o.height},
                    {"fxaa", true}, {"validation", o.validation}, {"whole_grid", o.whole_grid}}},
      {"paper_reference", {{"source", k_paper_source}, {"device", k_paper_device},
                           {"measure", "frames per second, one solver step plus rendering per frame"}}},
      {"results", json::array()},
      {"skipped", json::array()},
      {"wall_time_s", info.wall_time_s},
      {"validation_messages", info.validation_messages}};
  for (const Result& r : results) document["results"].push_back(result_json(r, o));
  for (const Skipped& k : info.skipped) document["skipped"].push_back({{"name", k.name}, {"reason", k.reason}});
  return document;
}

}  // namespace tools::benchmark
