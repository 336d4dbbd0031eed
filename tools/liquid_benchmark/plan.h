// The benchmark's settings and its plan: which configurations run (the paper's scenes, simulation
// only and with rendering, and the 2D scaling points), each with its scene as the benchmark
// changed it.
#pragma once

#include "tools/liquid_benchmark/paper_figures.h"

#include "liquid/scene.h"
#include "liquid/solver/grid_layout.h"

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tools::benchmark {

// The command line's settings.
struct Options {
  std::filesystem::path scenes_dir;
  std::filesystem::path json_path = "out/benchmark/benchmark.json";
  int warmup = 3;
  // About 2 minutes on a 2-core lavapipe machine (the 3D frames take 1 to 2 s there).
  int runs = 20;          // timed frames per paper configuration
  int scaling_runs = 10;  // timed frames per scaling point
  int steps_per_frame = 1;
  uint32_t width = 1024, height = 768;
  bool quick = false;
  bool scaling_only = false;
  bool no_scaling = false;
  bool list = false;
  bool validation = false;
  bool whole_grid = false;  // --whole-grid: 3D grid passes over every cell (LiquidOptions::active_region off)
  std::vector<std::string> only;
  // --3d-path: each 3D configuration once per path, named ".../<path>"; empty: once, on the
  // device's choice.
  std::vector<liquid::GridPath> paths_3d;
  // --splat-modes: each paper_* configuration once per splat mode (the scene's "splat" key), named
  // "paper_2d_64k:<mode>/sim" except the chapter's point_sprite, which keeps the plain name.
  std::vector<std::string> splat_modes = {"point_sprite", "separable"};
  bool splat_modes_given = false;  // asked for on the command line: a mode that cannot run is an error
  // --composite: paper_3d's raymarch composited into host targets of each colour and depth format,
  // as configurations "composite/<colour>+<depth>" (their first is today's RGBA8 + D32 path).
  bool composite = false;
  // --viewer: liquid_viewer's frame rate on the dam breaks, as configurations "viewer/<scene>".
  std::optional<std::filesystem::path> viewer;
  int viewer_frames = 0;  // per viewer run; 0: 60 in 2D, 20 in 3D
};

// The chapter's splat mode: the current behaviour, and a paper_* configuration's plain name.
inline constexpr const char* k_default_splat_mode = "point_sprite";

enum class Mode { Simulation, SimulationAndRender };

// One row of the tables and one entry of the JSON's results.
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
  std::optional<liquid::GridPath> grid_path;  // 3D: the path forced by --3d-path
  std::string splat_mode;                     // paper_* and scaling3d rows: the splat mode it runs; else empty
  std::filesystem::path scene_file;           // group "viewer": the file liquid_viewer opens
  // Group "composite": the host targets' formats the liquid is composited into.
  VkFormat composite_color = VK_FORMAT_UNDEFINED;
  VkFormat composite_depth = VK_FORMAT_UNDEFINED;
};

// Something the plan leaves out, and why (printed, and kept in the JSON's "skipped").
struct Skipped {
  std::string name, reason;
};

struct Plan {
  std::vector<Configuration> configurations;
  std::vector<Skipped> skipped;
};

// "sim" or "sim+render", as in the configuration names and the JSON's "mode".
const char* mode_name(Mode mode);

// The view pass a configuration draws ("none", "view2d", "raymarch", "height_field").
std::string view_name(const Configuration& c);

// "256x256" or "96x96x96".
std::string grid_label(glm::ivec3 grid);

// The configurations the options select, in run order; every scene is loaded and validated here,
// before any GPU work. Throws when a scene is bad, an --only value matches nothing, or a splat
// mode asked for by --splat-modes cannot run; a default splat mode this build's scenes do not
// know is skipped instead.
Plan make_plan(const Options& o);

}  // namespace tools::benchmark
