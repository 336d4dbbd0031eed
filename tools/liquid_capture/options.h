// The capture tool's flags, and the settled run they describe: the scene document after --set,
// the frame plan, the output names and the view. The settled run is what capture.json records, so
// --resume continues with exactly the same settings.
#pragma once

#include "tools/liquid_capture/frame_plan.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace capture {

// A bad flag or flag value found after parsing (the tool exits 2, as for CLI11's own errors).
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The ranges the flags take, and that a run record read back on --resume is held to (an edited or
// damaged capture.json is refused like a bad flag, not trusted).
inline constexpr int k_max_frame = 1000000;
inline constexpr int k_max_steps_per_frame = 100000;
inline constexpr int k_max_pixels = 65536;             // per side
inline constexpr double k_max_camera_coordinate = 1e6;  // m
inline constexpr double k_min_fov_degrees = 1.0, k_max_fov_degrees = 170.0;

struct CaptureOptions {
  std::string scene;              // a file, or a name in assets/scenes/
  std::vector<std::string> set;   // key=value scene overrides
  std::string out = "frames";     // a folder, or folder/name_####.png
  int start = 1;
  std::optional<int> end, frames;
  double fps = 0.0;               // 0: not given
  int steps_per_frame = 0;        // 0: not given
  uint32_t width = 1024, height = 768;
  std::vector<float> camera_position, camera_target;
  float fov_y_degrees = 0.0f;     // 0: the scene's
  bool fxaa = true, draw_particles = false;
  bool export_particles = false, export_volume = false, export_surface = false, export_whitewater = false;
  std::string particles_name, volume_name, surface_name, mesh_name, whitewater_name;
  std::optional<double> surface_voxel, surface_adaptivity;  // in cells; 0 to 1 (not given: the defaults)
  std::string surface_format;     // "ply" or "obj" (empty: ply)
  int checkpoint_every = 0;
  std::string resume, video;
  bool overwrite = false, dry_run = false, validation = false;
  std::string grid_path;          // --3d-path; empty: the device's (not part of the run: paths agree)
};

void add_options(CLI::App& app, CaptureOptions& options);

// Everything a run is, once the flags are settled; written to and read from capture.json.
struct RunSettings {
  std::string scene_source;       // the scene file the run started from
  std::string scene_document;     // its JSON after --set
  std::vector<std::string> overrides;
  FramePlan plan;
  // What scene messages name: the file, and that --set changed it.
  std::string scene_label() const { return scene_source + (overrides.empty() ? "" : " with --set"); }
  std::filesystem::path folder;
  NamePattern frames;
  std::optional<NamePattern> particles, volumes;
  // --export-surface: the level set (VDB) and the mesh (PLY or OBJ, by the pattern's extension).
  std::optional<NamePattern> surfaces, meshes;
  int surface_voxels_per_cell = 0;
  float surface_adaptivity = 0.0f;
  // --export-whitewater: the secondary particles (PLY); the scene must have "whitewater".
  std::optional<NamePattern> whitewater;
  // The outputs asked for besides the frames, each with the flag that names it, in a fixed order.
  std::vector<std::pair<const NamePattern*, const char*>> optional_outputs() const {
    std::vector<std::pair<const NamePattern*, const char*>> out;
    for (const auto& [pattern, flag] : {std::pair{&particles, "--particles-name"}, {&whitewater, "--whitewater-name"},
                                        {&volumes, "--volume-name"}, {&surfaces, "--surface-name"},
                                        {&meshes, "--mesh-name"}})
      if (*pattern) out.emplace_back(&**pattern, flag);
    return out;
  }
  // Whether a written frame's files read the grids back (rebuilt first for the frame's instant).
  bool exports_grids() const { return particles || volumes || surfaces; }
  // Whether a written frame reads the secondary particles back: for their own files, and for the
  // volume's foam grid when the scene has them.
  bool reads_whitewater(bool scene_has_whitewater) const { return whitewater || (volumes && scene_has_whitewater); }
  uint32_t width = 0, height = 0;
  bool fxaa = true, draw_particles = false;
  std::vector<float> camera_position, camera_target;  // empty: the scene's camera
  float fov_y_degrees = 0.0f;
  int checkpoint_every = 0;
  std::string video;              // empty: none
};

// Resolves the scene (path or name), applies --set, plans the frames and names the files. Throws
// UsageError for a bad combination of flags and SceneError for a bad scene.
RunSettings settle(const CaptureOptions& options, int max_steps_per_frame);

// With --resume only --validation and --3d-path may be given; throws UsageError naming the first
// other flag.
void check_resume_flags(const CLI::App& app);

nlohmann::json to_json(const RunSettings& settings);
// Throws std::runtime_error naming `source` when the record is not one this tool wrote.
RunSettings run_settings_from_json(const nlohmann::json& record, const std::filesystem::path& folder,
                                   const std::string& source);

// A scene given by name ("dam_break_2d") is looked up in ./assets/scenes/, then in the source tree's.
std::filesystem::path resolve_scene(const std::string& name_or_path);

}  // namespace capture
