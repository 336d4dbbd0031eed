// liquid_benchmark: times the chapter's configurations headless (simulation only, and simulation
// plus rendering at 1024x768 with FXAA) and 2D scaling runs over particle count and grid size.
// Reports wall time per frame and step, the GPU time of every pass, steps and particles per
// second, beside the paper's Quadro 2000M figures: a table on the terminal and a JSON file that
// tools/plot_benchmark.py turns into charts.
#include "engine/io/atomic_file.h"
#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "engine/vk/context.h"
#include "liquid/node.h"
#include "liquid/render/camera.h"
#include "liquid/render/renderer.h"
#include "liquid/scene.h"
#include "liquid/setup.h"

#include "tools/cli.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#ifndef LIQUID_SOURCE_DIR
#define LIQUID_SOURCE_DIR "."
#endif

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------
// The paper's figures (Guay, "Simple, Rasterization-based Liquids", GPU Pro 5, section 7), all
// measured on an NVIDIA Quadro 2000M with one solver step and the rendering per frame.

struct PaperFigure {
  double fps = 0.0;      // the chapter's method, simulation + rendering
  double sph_fps = 0.0;  // the DirectX 11 SDK SPH sample on the same laptop (2D only); 0 = none
  std::string what;
};

std::optional<PaperFigure> paper_figure(const std::string& scene) {
  if (scene == "paper_2d_16k") return PaperFigure{830, 567, "2D, 256^2 grid, 16k particles"};
  if (scene == "paper_2d_32k") return PaperFigure{510, 325, "2D, 256^2 grid, 32k particles"};
  if (scene == "paper_2d_64k") return PaperFigure{296, 169, "2D, 256^2 grid, 64k particles"};
  if (scene == "paper_3d") return PaperFigure{35, 0, "3D, 96^3 grid, 125k particles, raymarch + FXAA at 1024x768"};
  if (scene == "shallow_water") return PaperFigure{130, 0, "shallow water, 256^2 grid, 42k particles"};
  return std::nullopt;
}

const char* k_paper_device = "NVIDIA Quadro 2000M";
const char* k_paper_source = "M. Guay, Simple, Rasterization-based Liquids, GPU Pro 5 (2014), section 7";

// ---------------------------------------------------------------------------------------------
// Settings and the plan of configurations

struct Options {
  fs::path scenes_dir;
  fs::path json_path = "out/benchmark/benchmark.json";
  int warmup = 3;
  // About 2 minutes on the 2-core lavapipe machine (the 3D frames take 1 to 2 s there).
  int runs = 20;          // timed frames per paper configuration
  int scaling_runs = 10;  // timed frames per scaling point
  int steps_per_frame = 1;
  uint32_t width = 1024, height = 768;
  bool quick = false;
  bool scaling_only = false;
  bool no_scaling = false;
  bool list = false;
  bool validation = false;
  std::vector<std::string> only;
};

enum class Mode { Simulation, SimulationAndRender };

struct Configuration {
  std::string name;   // e.g. "paper_2d_64k/sim+render", "scaling/particles/128k"
  std::string group;  // "paper" or "scaling"
  std::string scene_name;
  std::string note;   // how the scene file was changed for the benchmark, if it was
  liquid::Scene scene;
  Mode mode = Mode::Simulation;
  int timed_frames = 0;
  std::optional<PaperFigure> paper;  // sim+render rows of the paper's scenes only
  int particles = 0;                 // active at the start (no configuration here emits)
  glm::ivec3 grid{1};
  double expected_ms = 0.0;  // per frame on the 2-core lavapipe reference machine (time estimate)
};

const char* mode_name(Mode mode) { return mode == Mode::Simulation ? "sim" : "sim+render"; }

std::string view_name(const Configuration& c) {
  if (c.mode == Mode::Simulation) return "none";
  if (c.scene.mode == liquid::SimulationMode::ShallowWater) return "height_field";
  return c.scene.dimension == 3 ? "raymarch" : "view2d";
}

// The jet of paper_3d needs ~3 s of simulated time (~17,000 steps) to add its 26,720 particles,
// but the paper's 35 fps is for the scene at capacity (~125k). So the emitter's particles are
// placed up front as a cube of liquid near the top of the domain, above the spheres: the
// benchmark then runs the full count from the first frame.
std::string fill_emitters_up_front(liquid::Scene& scene) {
  int capacity = 0;
  for (const liquid::Emitter& e : scene.emitters) capacity += e.capacity;
  if (capacity == 0 || scene.dimension != 3) return "";
  scene.emitters.clear();
  const int side = int(std::lround(std::cbrt(double(capacity))));
  const float s = scene.particle_spacing;
  // (side + 0.5) spacings hold exactly `side` lattice points whatever the float rounding.
  const float edge = (float(side) + 0.5f) * s;
  const glm::vec3 d = scene.domain;
  const float top = d.y - 0.05f * d.y;
  scene.fluid_blocks.push_back({glm::vec3(0.5f * (d.x - edge), top - edge, 0.5f * (d.z - edge)),
                                glm::vec3(0.5f * (d.x + edge), top, 0.5f * (d.z + edge)), glm::vec3(0.0f)});
  return "the emitter's " + std::to_string(capacity) + " particles are replaced by a " + std::to_string(side) +
         "^3 block (" + std::to_string(side * side * side) +
         " particles) above the spheres, so the scene runs at capacity from the first frame";
}

// A 2D scene with one block of about `count` particles on its lattice (the block's shape kept).
liquid::Scene with_particle_count(liquid::Scene scene, int count) {
  if (scene.fluid_blocks.empty()) throw std::invalid_argument(scene.name + ": the scaling runs need a fluid block");
  scene.fluid_blocks.resize(1);
  const glm::vec3 extent = scene.fluid_blocks[0].max - scene.fluid_blocks[0].min;
  scene.particle_spacing = float(std::sqrt(double(extent.x) * extent.y / count));
  return scene;
}

// The wall margin follows the spacing roughly as in the paper_2d_* files (0.4 spacings, in cells,
// at most 0.45), so the lattice's outer particles start inside the margin.
void set_wall_margin(liquid::Scene& scene) {
  const double longest = std::max(scene.domain.x, scene.domain.y);
  const double cell = longest / scene.grid_resolution.value_or(256);
  scene.wall_margin_cells = float(std::min(0.45, 0.4 * scene.particle_spacing / cell));
}

// Rough frame cost on the 2-core lavapipe reference machine, in ms, used only to print how long
// the run will take: per-particle costs (splat and particle passes; a 3D splat draws 7 slices per
// particle), a per-cell cost (grid pass) and a per-pixel cost for the view and FXAA, fitted to
// runs on that machine. The progress lines correct it with the times this machine shows.
double expected_frame_ms(const Configuration& c, const Options& o) {
  const double particles = c.particles, cells = double(c.grid.x) * c.grid.y * c.grid.z;
  const bool three_d = c.scene.dimension == 3;
  // Fitted to the 11:03 UTC run of 2026-11-25 (README, Benchmark).
  double ms = three_d ? 2.7e-3 * particles + 2.0e-5 * cells : 5.4e-4 * particles + 4.5e-5 * cells;
  ms = ms * o.steps_per_frame + 1.0;
  if (c.mode == Mode::SimulationAndRender) {
    const double pixels = double(o.width) * o.height;
    const double view = three_d ? 5.3e-4 : c.scene.mode == liquid::SimulationMode::ShallowWater ? 1.55e-4 : 2.6e-5;
    ms += (view + 4.5e-5) * pixels;  // the view, then FXAA
  }
  return ms;
}

liquid::Scene load_named_scene(const Options& o, const std::string& name) {
  return liquid::load_scene(o.scenes_dir / (name + ".json"));
}

Configuration make_configuration(std::string name, std::string group, std::string scene_name, liquid::Scene scene,
                                 Mode mode, int frames, const Options& o) {
  Configuration c;
  c.name = std::move(name);
  c.group = std::move(group);
  c.scene_name = std::move(scene_name);
  c.note = fill_emitters_up_front(scene);
  c.scene = std::move(scene);
  c.mode = mode;
  c.timed_frames = frames;
  if (mode == Mode::SimulationAndRender && c.group == "paper") c.paper = paper_figure(c.scene_name);
  // The CPU-side setup validates the scene now, before any GPU work (the node checks it again
  // against the device's real limits).
  const liquid::SimulationSetup setup = liquid::make_setup(c.scene, liquid::DeviceLimits{});
  c.particles = setup.initial_particles;
  c.grid = setup.grid_cells;
  c.expected_ms = expected_frame_ms(c, o);
  return c;
}

std::vector<Configuration> paper_configurations(const Options& o) {
  std::vector<Configuration> out;
  for (const char* name : {"paper_2d_16k", "paper_2d_32k", "paper_2d_64k", "shallow_water", "paper_3d"}) {
    const liquid::Scene scene = load_named_scene(o, name);
    for (Mode mode : {Mode::Simulation, Mode::SimulationAndRender})
      out.push_back(make_configuration(std::string(name) + "/" + mode_name(mode), "paper", name, scene, mode, o.runs, o));
  }
  return out;
}

// Simulation only, from paper_2d_64k: particle count 16k..256k on its 256^2 grid, then grid
// 128^2..1024^2 at 64k particles (the 256^2 point is shared with the first curve).
std::vector<Configuration> scaling_configurations(const Options& o) {
  const std::string base_name = "paper_2d_64k";
  const liquid::Scene base = load_named_scene(o, base_name);
  std::vector<Configuration> out;
  for (int k : {16, 32, 64, 128, 256}) {
    liquid::Scene scene = with_particle_count(base, k * 1000);
    scene.grid_resolution = 256;
    set_wall_margin(scene);
    out.push_back(make_configuration("scaling/particles/" + std::to_string(k) + "k", "scaling", base_name, scene,
                                     Mode::Simulation, o.scaling_runs, o));
  }
  for (int resolution : {128, 512, 1024}) {
    liquid::Scene scene = with_particle_count(base, 64 * 1000);
    scene.grid_resolution = resolution;
    set_wall_margin(scene);
    out.push_back(make_configuration("scaling/grid/" + std::to_string(resolution), "scaling", base_name, scene,
                                     Mode::Simulation, o.scaling_runs, o));
  }
  for (Configuration& c : out)
    c.note = "paper_2d_64k with one block of " + std::to_string(c.particles) + " particles on a " +
             std::to_string(c.grid.x) + "^2 grid (spacing " + std::to_string(c.scene.particle_spacing) + " m)";
  return out;
}

// A --only value selects the configuration of that exact name, else every name containing it
// ("paper_2d_64k/sim" is one configuration, "paper_2d" six).
bool matches(const std::string& name, const std::string& pattern, const std::vector<Configuration>& all) {
  const bool exact_exists =
      std::any_of(all.begin(), all.end(), [&](const Configuration& c) { return c.name == pattern; });
  return exact_exists ? name == pattern : name.find(pattern) != std::string::npos;
}

std::vector<Configuration> make_plan(const Options& o) {
  std::vector<Configuration> all;
  if (!o.scaling_only) all = paper_configurations(o);
  if (!o.no_scaling) {
    auto scaling = scaling_configurations(o);
    all.insert(all.end(), scaling.begin(), scaling.end());
  }
  for (const std::string& s : o.only)
    if (std::none_of(all.begin(), all.end(), [&](const Configuration& c) { return matches(c.name, s, all); }))
      throw std::invalid_argument("--only " + s + ": matches no configuration (see --list)");
  std::vector<bool> keep(all.size(), o.only.empty());
  for (size_t i = 0; i < all.size(); ++i)
    for (const std::string& s : o.only) keep[i] = keep[i] || matches(all[i].name, s, all);
  std::vector<Configuration> plan;
  for (size_t i = 0; i < all.size(); ++i)
    if (keep[i]) plan.push_back(std::move(all[i]));
  return plan;
}

// Seconds per configuration: its frames, plus a setup cost (pipelines, upload, a final check).
double expected_seconds(const Configuration& c, const Options& o) {
  return (o.warmup + c.timed_frames) * c.expected_ms * 1e-3 + 0.5;
}

// ---------------------------------------------------------------------------------------------
// Running one configuration

struct Stats {
  double median = 0.0, min = 0.0, max = 0.0;
};

Stats stats_of(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

struct Result {
  const Configuration* config = nullptr;
  int active_particles = 0;
  std::vector<double> frame_ms;                          // wall, per timed frame
  std::vector<std::string> pass_order;                   // as first declared
  std::map<std::string, std::vector<double>> pass_ms;   // GPU, per timed frame, summed over repeats
  std::vector<double> solver_gpu_ms, render_gpu_ms;      // per timed frame
  double setup_s = 0.0, total_s = 0.0;
  std::string stability = "stable";
};

bool is_solver_pass(const std::string& name) {
  return name == "liquid.splat" || name == "liquid.grid" || name == "liquid.particle";
}

// The node, its renderer and a graph, as a host engine would hold them.
struct Bench {
  Bench(engine::vk::Context& context, const Configuration& c, const Options& o)
      : steps(o.steps_per_frame),
        node(context, c.scene, liquid::LiquidOptions{.frames_in_flight = 1, .max_steps_per_frame = o.steps_per_frame}),
        graph(&context),
        cmd(context) {
    if (c.mode == Mode::SimulationAndRender) {
      renderer = std::make_unique<liquid::LiquidRenderer>(
          context, node, liquid::RenderSettings{.width = o.width, .height = o.height, .fxaa = true});
      camera = liquid::default_camera(node.setup());
    }
  }
  int steps;
  liquid::LiquidNode node;
  std::unique_ptr<liquid::LiquidRenderer> renderer;
  liquid::CameraView camera;
  engine::graph::RenderGraph graph;
  engine::vk::CommandBuffer cmd;
};

// One frame: declare and compile the graph (CPU, not timed), then time from recording to the
// fence: the wall time of one submission run to completion.
double run_frame(Bench& b) {
  b.graph.reset();
  const liquid::LiquidImages images = b.node.add_to(b.graph, b.steps);
  if (b.renderer) b.renderer->add_to(b.graph, images, b.camera);
  b.graph.compile();
  const auto start = Clock::now();
  b.graph.execute(b.cmd.begin());
  b.cmd.submit_and_wait();
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void record_timings(Result& r, const std::vector<engine::graph::PassTiming>& timings) {
  std::map<std::string, double> frame;
  double solver = 0.0, render = 0.0;
  for (const auto& t : timings) {
    if (!frame.count(t.name) && std::find(r.pass_order.begin(), r.pass_order.end(), t.name) == r.pass_order.end())
      r.pass_order.push_back(t.name);
    frame[t.name] += t.milliseconds;
    (is_solver_pass(t.name) ? solver : render) += t.milliseconds;
  }
  for (const auto& [name, ms] : frame) r.pass_ms[name].push_back(ms);
  r.solver_gpu_ms.push_back(solver);
  r.render_gpu_ms.push_back(render);
}

// The state after the timed frames: a benchmark of a blown-up simulation would be meaningless.
std::string check_stability(liquid::LiquidNode& node) {
  try {
    const liquid::Diagnostics d = node.diagnose();
    if (d.non_finite > 0) return std::to_string(d.non_finite) + " non-finite particles";
    return "stable";
  } catch (const liquid::SimulationError& error) {
    return error.what();
  }
}

Result run_configuration(engine::vk::Context& context, const Configuration& c, const Options& o) {
  Result r;
  r.config = &c;
  const auto start = Clock::now();
  Bench bench(context, c, o);
  r.setup_s = seconds_since(start);
  for (int i = 0; i < o.warmup; ++i) run_frame(bench);
  for (int i = 0; i < c.timed_frames; ++i) {
    r.frame_ms.push_back(run_frame(bench));
    record_timings(r, bench.graph.read_timings());
  }
  r.active_particles = bench.node.active_particles();
  r.stability = check_stability(bench.node);
  r.total_s = seconds_since(start);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Derived figures, the terminal tables and the JSON

struct Figures {
  Stats frame, step, solver_gpu_step, render_gpu;
  double fps = 0.0, steps_per_second = 0.0, particles_per_second = 0.0;
};

Figures figures_of(const Result& r, int steps_per_frame) {
  Figures f;
  f.frame = stats_of(r.frame_ms);
  // Wall time per step is the frame's divided by its steps: in sim+render runs it carries the
  // rendering's share too; the solver's own GPU time per step is solver_gpu_step.
  f.step = {f.frame.median / steps_per_frame, f.frame.min / steps_per_frame, f.frame.max / steps_per_frame};
  std::vector<double> solver_step;
  for (double ms : r.solver_gpu_ms) solver_step.push_back(ms / steps_per_frame);
  f.solver_gpu_step = stats_of(solver_step);
  f.render_gpu = stats_of(r.render_gpu_ms);
  f.fps = f.frame.median > 0 ? 1000.0 / f.frame.median : 0.0;
  f.steps_per_second = f.fps * steps_per_frame;
  f.particles_per_second = f.steps_per_second * r.active_particles;
  return f;
}

std::string short_pass_name(const std::string& name) {
  return name.rfind("liquid.", 0) == 0 ? name.substr(7) : name;
}

std::string grid_label(glm::ivec3 g) {
  return g.z > 1 ? std::to_string(g.x) + "x" + std::to_string(g.y) + "x" + std::to_string(g.z)
                 : std::to_string(g.x) + "x" + std::to_string(g.y);
}

void print_wall_table(const std::vector<Result>& results, const Options& o) {
  std::printf("\nWall time (recording to fence, one submission per frame, %d step(s) per frame)\n", o.steps_per_frame);
  std::printf("%-27s %8s %10s | %8s %8s %8s | %8s %8s %8s | %8s %9s %7s %s\n", "configuration", "particles", "grid",
              "frame ms", "min", "max", "step ms", "min", "max", "steps/s", "Mpart/s", "fps", "");
  for (const Result& r : results) {
    const Figures f = figures_of(r, o.steps_per_frame);
    std::printf("%-27s %8d %10s | %8.2f %8.2f %8.2f | %8.2f %8.2f %8.2f | %8.2f %9.3f %7.2f %s\n",
                r.config->name.c_str(), r.active_particles, grid_label(r.config->grid).c_str(), f.frame.median,
                f.frame.min, f.frame.max, f.step.median, f.step.min, f.step.max, f.steps_per_second,
                f.particles_per_second * 1e-6, f.fps, r.stability == "stable" ? "" : "UNSTABLE");
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
  std::printf("%-27s %9s %9s | %9s %9s | %9s %9s | %10s\n", "configuration", "ours fps", "ours ms", "paper fps",
              "paper ms", "SPH fps", "SPH ms", "ours/paper");
  for (const Result& r : results) {
    if (!r.config->paper) continue;
    const Figures f = figures_of(r, o.steps_per_frame);
    const PaperFigure& p = *r.config->paper;
    const std::string sph_fps = p.sph_fps > 0 ? std::to_string(int(p.sph_fps)) : "-";
    char sph_ms[32] = "-";
    if (p.sph_fps > 0) std::snprintf(sph_ms, sizeof sph_ms, "%.2f", 1000.0 / p.sph_fps);
    std::printf("%-27s %9.2f %9.2f | %9.0f %9.2f | %9s %9s | %10.4f\n", r.config->name.c_str(), f.fps,
                f.frame.median, p.fps, 1000.0 / p.fps, sph_fps.c_str(), sph_ms, f.fps / p.fps);
  }
}

// Pass columns in pipeline order: the solver's three passes, then the views, then FXAA.
std::vector<std::string> pass_columns(const std::vector<Result>& results) {
  const std::vector<std::string> order = {"liquid.splat",    "liquid.grid",   "liquid.particle",     "liquid.occupancy",
                                          "liquid.raymarch", "liquid.view2d", "liquid.height_field", "fxaa"};
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
  std::printf("\nGPU time per pass (median ms per frame, from the graph's timestamps)\n%-27s", "configuration");
  for (const std::string& name : columns) std::printf(" %12s", short_pass_name(name).c_str());
  std::printf(" %12s\n", "sum");
  for (const Result& r : results) {
    std::printf("%-27s", r.config->name.c_str());
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
            {"stability", r.stability},
            {"note", c.note}};
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

// ---------------------------------------------------------------------------------------------

void print_plan(const std::vector<Configuration>& plan, const Options& o) {
  double total = 0.0;
  for (const Configuration& c : plan) total += expected_seconds(c, o);
  std::printf("%zu configuration(s); %d warm-up frame(s) (not timed) then %d timed frame(s) each (%d per scaling "
              "point); %d step(s) per frame; frames %ux%u with FXAA\n",
              plan.size(), o.warmup, o.runs, o.scaling_runs, o.steps_per_frame, o.width, o.height);
  std::printf("estimated time on the 2-core lavapipe reference machine: %.0f s (a GPU takes far less)\n", total);
}

void list_plan(const std::vector<Configuration>& plan, const Options& o) {
  for (const Configuration& c : plan)
    std::printf("%-27s %8d particles, grid %-10s ~%6.1f s on lavapipe%s%s\n", c.name.c_str(), c.particles,
                grid_label(c.grid).c_str(), expected_seconds(c, o), c.note.empty() ? "" : "  -- ", c.note.c_str());
}

int run(const Options& o, const std::string& command_line) {
  const auto start = Clock::now();
  const std::vector<Configuration> plan = make_plan(o);
  if (o.list) {
    list_plan(plan, o);
    return 0;
  }
  // Fail now, not after minutes of measuring, when the JSON cannot be written.
  engine::io::ensure_writable_folder(o.json_path.has_parent_path() ? o.json_path.parent_path() : fs::path("."));
  engine::vk::Context context(engine::vk::ContextOptions{.validation = o.validation});
  std::printf("device: %s; driver: %s; host: %u hardware threads\n", context.device_name().c_str(),
              context.driver_description().c_str(), std::thread::hardware_concurrency());
  print_plan(plan, o);

  std::vector<Result> results;
  double expected_done = 0.0, expected_total = 0.0;
  for (const Configuration& c : plan) expected_total += expected_seconds(c, o);
  for (size_t i = 0; i < plan.size(); ++i) {
    results.push_back(run_configuration(context, plan[i], o));
    expected_done += expected_seconds(plan[i], o);
    // The reference machine's estimate, scaled by how this machine has done so far.
    const double elapsed = seconds_since(start);
    const double left = (expected_total - expected_done) * elapsed / expected_done;
    const Figures f = figures_of(results.back(), o.steps_per_frame);
    std::printf("[%2zu/%zu] %-27s %9.2f ms/frame  (%5.1f s; %.0f s elapsed, ~%.0f s left)\n", i + 1, plan.size(),
                plan[i].name.c_str(), f.frame.median, results.back().total_s, elapsed, left);
    std::fflush(stdout);
  }

  print_wall_table(results, o);
  print_paper_table(results, o);
  print_pass_table(results);

  const double wall_s = seconds_since(start);
  json document = {
      {"tool", "liquid_benchmark"},
      {"date", utc_now()},
      {"command", command_line},
      {"device", {{"name", context.device_name()}, {"driver", context.driver_description()},
                  {"cpu_device", context.is_cpu_device()}}},
      {"host", {{"hardware_threads", std::thread::hardware_concurrency()},
                {"LP_NUM_THREADS", std::getenv("LP_NUM_THREADS") ? json(std::getenv("LP_NUM_THREADS")) : json(nullptr)}}},
      {"settings", {{"warmup_frames", o.warmup}, {"timed_frames", o.runs}, {"scaling_timed_frames", o.scaling_runs},
                    {"steps_per_frame", o.steps_per_frame}, {"frame_width", o.width}, {"frame_height", o.height},
                    {"fxaa", true}, {"validation", o.validation}}},
      {"paper_reference", {{"source", k_paper_source}, {"device", k_paper_device},
                           {"measure", "frames per second, one solver step plus rendering per frame"}}},
      {"results", json::array()},
      {"wall_time_s", wall_s}};
  for (const Result& r : results) document["results"].push_back(result_json(r, o));
  const uint32_t messages = context.validation_message_count();
  document["validation_messages"] = messages;
  engine::io::write_file_atomically(o.json_path, document.dump(2) + "\n");
  std::printf("\nwrote %s; total wall time %.1f s\n", o.json_path.string().c_str(), wall_s);
  if (o.validation) std::printf("validation messages: %u\n", messages);

  if (o.validation && messages > 0) {
    std::fprintf(stderr, "liquid_benchmark: error: %u validation message(s)\n", messages);
    return 1;
  }
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
  auto* warmup = app.add_option("--warmup", o.warmup, "untimed frames before timing")->check(CLI::Range(0, 1000));
  auto* runs = app.add_option("--runs", o.runs, "timed frames per paper configuration")->check(CLI::Range(1, 100000));
  auto* scaling_runs =
      app.add_option("--scaling-runs", o.scaling_runs, "timed frames per scaling point")->check(CLI::Range(1, 100000));
  app.add_option("--steps-per-frame", o.steps_per_frame, "solver steps per frame (the paper: 1)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--width", o.width, "frame width in pixels")->check(CLI::Range(16u, 16384u));
  app.add_option("--height", o.height, "frame height in pixels")->check(CLI::Range(16u, 16384u));
  app.add_option("--only", o.only, "run only configurations whose name contains this (repeatable; see --list)");
  app.add_flag("--quick", o.quick, "a short run: 1 warm-up and 2 timed frames unless given");
  auto* scaling = app.add_flag("--scaling", o.scaling_only, "run only the scaling set");
  app.add_flag("--no-scaling", o.no_scaling, "skip the scaling set")->excludes(scaling);
  app.add_flag("--list", o.list, "list the configurations and their estimated times, run nothing");
  app.add_flag("--validation", o.validation, "enable the Vulkan validation layer (exit 1 on any message)");
  if (const auto exit_code = tools::parse_arguments(app, argc, argv, "liquid_benchmark")) return *exit_code;
  if (o.quick) {
    if (warmup->count() == 0) o.warmup = 1;
    if (runs->count() == 0) o.runs = 2;
    if (scaling_runs->count() == 0) o.scaling_runs = 2;
  }
  try {
    return run(o, join_arguments(argc, argv));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "liquid_benchmark: error: %s\n", error.what());
    return 1;
  }
}
