#include "tools/liquid_capture/options.h"

#include "tools/common/grid_path_flag.h"

#include "liquid/export/surface.h"
#include "liquid/physics/time_step.h"
#include "liquid/scene.h"
#include "liquid/scene/format.h"
#include "liquid/scene/override.h"
#include "tools/common/cli.h"

#include <algorithm>
#include <cmath>
#include <set>

#ifndef LIQUID_SOURCE_DIR
#define LIQUID_SOURCE_DIR "."
#endif

namespace capture {

namespace fs = std::filesystem;
using nlohmann::json;

void add_options(CLI::App& app, CaptureOptions& o) {
  using tools::finite_range;
  using tools::integer_range;
  using tools::non_empty;
  app.add_option("scene", o.scene, "scene JSON file, or the name of one in assets/scenes/ (dam_break_2d)");
  app.add_option("-o,--out", o.out, "output folder, or a frame name pattern in it (out/liquid_####.png)")
      ->take_last()
      ->check(non_empty("a folder or a frame name pattern"));
  app.add_option("-s,--start", o.start, "first frame written (0: the initial state)")->check(integer_range(0, k_max_frame));
  app.add_option("-e,--end", o.end, "last frame written")->check(integer_range(0, k_max_frame));
  app.add_option("-n,--frames", o.frames, "frames written (default 60): sets --end to start + N - 1")
      ->check(integer_range(1, k_max_frame));
  app.add_option("--fps", o.fps, "simulated frames per second (steps per frame = 1 / (fps dt)); "
                                 "default: the scene's substeps per frame")
      ->check(finite_range(0.001, 10000.0));
  app.add_option("--steps-per-frame", o.steps_per_frame, "simulation steps per frame (overrides --fps)")
      ->check(integer_range(1, k_max_steps_per_frame));
  app.add_option("--width", o.width, "frame width in pixels")->check(integer_range(1, k_max_pixels));
  app.add_option("--height", o.height, "frame height in pixels")->check(integer_range(1, k_max_pixels));
  app.add_option("--camera-position", o.camera_position, "camera position x,y,z (m); default: the scene's")
      ->expected(3)
      ->delimiter(',')
      ->check(finite_range(-k_max_camera_coordinate, k_max_camera_coordinate));
  app.add_option("--camera-target", o.camera_target, "point the camera looks at x,y,z (m)")
      ->expected(3)
      ->delimiter(',')
      ->check(finite_range(-k_max_camera_coordinate, k_max_camera_coordinate));
  app.add_option("--fov", o.fov_y_degrees, "vertical field of view (degrees)")->check(finite_range(k_min_fov_degrees, k_max_fov_degrees));
  app.add_flag("!--no-fxaa", o.fxaa, "skip the FXAA pass");
  app.add_flag("--draw-particles", o.draw_particles, "2D views: draw the particles as points over the liquid");
  app.add_flag("--export-particles", o.export_particles,
               "write each frame's particles as binary PLY (x y z vx vy vz id density)");
  app.add_option("--particles-name", o.particles_name, "PLY name pattern (default particles_#####.ply); "
                                                       "implies --export-particles")
      ->check(non_empty("a name pattern"));
  app.add_flag("--export-whitewater", o.export_whitewater,
               "write each frame's spray, foam and bubble particles as binary PLY (x y z vx vy vz type age "
               "id_hi id_lo); the scene needs \"whitewater\"");
  app.add_option("--whitewater-name", o.whitewater_name, "whitewater PLY name pattern (default "
                                                         "whitewater_#####.ply); implies --export-whitewater")
      ->check(non_empty("a name pattern"));
  app.add_flag("--export-volume", o.export_volume,
               "write each frame's density and velocity grids, and with whitewater the foam's, as OpenVDB");
  app.add_option("--volume-name", o.volume_name, "VDB name pattern (default volume_#####.vdb); implies --export-volume")
      ->check(non_empty("a name pattern"));
  app.add_flag("--export-surface", o.export_surface,
               "write each frame's liquid surface: a level-set VDB (grid 'surface') and a triangle mesh");
  app.add_option("--surface-name", o.surface_name, "level-set VDB name pattern (default surface_#####.vdb); "
                                                   "implies --export-surface")
      ->check(non_empty("a name pattern"));
  app.add_option("--mesh-name", o.mesh_name, "mesh name pattern (default mesh_#####.ply, .obj with "
                                             "--surface-format obj); implies --export-surface")
      ->check(non_empty("a name pattern"));
  app.add_option("--surface-voxel", o.surface_voxel, "surface voxel size in density-grid cells: a cell divided by "
                                                     "1 to 8 (1, 0.5, 0.333, 0.25, ..., 0.125; default 0.5)")
      ->check(finite_range(1.0 / liquid::k_max_surface_voxels_per_cell, 1.0));
  app.add_option("--surface-adaptivity", o.surface_adaptivity, "mesh adaptivity, 0 (every voxel) to 1 (default 0)")
      ->check(finite_range(0.0, 1.0));
  app.add_option("--surface-format", o.surface_format, "mesh file format: ply (with vertex velocities) or obj")
      ->check(CLI::IsMember({"ply", "obj"}));
  app.add_option("--set", o.set, "override a scene field: key=value, dotted paths (fluid_blocks.0.max=[0.1,0.2,0.2])")
      ->take_all();
  app.add_option("--checkpoint-every", o.checkpoint_every, "save a checkpoint every N frames (for --resume)")
      ->check(integer_range(1, k_max_frame));
  app.add_option("--resume", o.resume, "continue the run in FOLDER from its last checkpoint")
      ->check(non_empty("a capture folder"));
  app.add_option("--video", o.video, "also encode the frames with ffmpeg (.mp4, .mkv or .mov)")
      ->check(non_empty("a file name"));
  app.add_flag("--overwrite", o.overwrite, "replace another capture's files in the output folder");
  app.add_flag("--dry-run", o.dry_run, "print the resolved scene, the frame plan and a time estimate; write nothing");
  app.add_flag("--validation", o.validation, "enable the Vulkan validation layer; any message fails the run");
  tools::add_grid_path_option(app, o.grid_path);
}

fs::path resolve_scene(const std::string& name) {
  const fs::path given(name);
  if (fs::exists(given) || given.has_parent_path()) return given;  // load_scene() reports a missing path
  const fs::path file = given.extension() == ".json" ? given : fs::path(name + ".json");
  const fs::path dirs[] = {"assets/scenes", fs::path(LIQUID_SOURCE_DIR) / "assets" / "scenes"};
  for (const fs::path& dir : dirs)
    if (fs::is_regular_file(dir / file)) return dir / file;
  std::set<std::string> shipped;
  for (const fs::path& dir : dirs)
    if (fs::is_directory(dir))
      for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".json") shipped.insert(entry.path().stem().string());
  std::string list;
  for (const std::string& s : shipped) list += (list.empty() ? "" : ", ") + s;
  throw liquid::SceneError(name + ": no such scene file, nor a scene of that name in assets/scenes/" +
                           (list.empty() ? "" : " (" + list + ")"));
}

namespace {

// Every output's name, at the run's last frame and with the .partial its temporary adds, within
// what a file system takes (NAME_MAX, 255 bytes on Linux): refused before the run, not at its first
// write, which left a started run behind.
constexpr size_t k_max_file_name_bytes = 255;
constexpr size_t k_temporary_suffix_bytes = sizeof(".partial") - 1;

void check_name_lengths(const RunSettings& r) {
  const auto check = [&](const NamePattern& pattern, const char* what) {
    const std::string longest = pattern.name(r.plan.end);
    if (longest.size() + k_temporary_suffix_bytes > k_max_file_name_bytes)
      throw std::invalid_argument(std::string(what) + " " + liquid::printable(pattern.text()) + ": frame " +
                                  std::to_string(r.plan.end) + "'s name is " + std::to_string(longest.size()) +
                                  " bytes, and with its temporary .partial past the " +
                                  std::to_string(k_max_file_name_bytes) + " a file name may have");
  };
  check(r.frames, "-o");
  for (const auto& [pattern, flag] : r.optional_outputs()) check(*pattern, flag);
  if (!r.video.empty() && fs::path(r.video).filename().string().size() + k_temporary_suffix_bytes > k_max_file_name_bytes)
    throw std::invalid_argument("--video " + liquid::printable(r.video) + ": the file name is longer than " +
                                std::to_string(k_max_file_name_bytes - k_temporary_suffix_bytes) + " bytes");
}

// --export-surface and the flags that shape it (which need it, or imply it by naming a file).
void settle_surface(const CaptureOptions& o, RunSettings& r) {
  const bool named = !o.surface_name.empty() || !o.mesh_name.empty();
  if (!o.export_surface && !named) {
    if (o.surface_voxel || o.surface_adaptivity || !o.surface_format.empty())
      throw UsageError(std::string(o.surface_voxel ? "--surface-voxel" : o.surface_adaptivity ? "--surface-adaptivity"
                                                                                                : "--surface-format") +
                       " shapes the surface export: give --export-surface too");
    return;
  }
  const std::string format = o.surface_format.empty() ? "ply" : o.surface_format;
  r.surfaces = NamePattern::parse(o.surface_name.empty() ? "surface_#####.vdb" : o.surface_name, "--surface-name", ".vdb");
  r.meshes = NamePattern::parse(o.mesh_name.empty() ? "mesh_#####." + format : o.mesh_name, "--mesh-name", "." + format);
  r.surface_voxels_per_cell = liquid::SurfaceSettings{}.voxels_per_cell;
  if (o.surface_voxel) {
    // Voxel faces meet the walls only if a whole number of voxels fills a cell.
    r.surface_voxels_per_cell = int(std::lround(1.0 / *o.surface_voxel));
    if (std::abs(r.surface_voxels_per_cell * double(*o.surface_voxel) - 1.0) > 2e-3)
      throw UsageError("--surface-voxel " + tools::format_cli_number(*o.surface_voxel) +
                       ": must be a cell divided by a whole number from 1 to " +
                       std::to_string(liquid::k_max_surface_voxels_per_cell) + " (1, 0.5, 0.333, 0.25, ..., 0.125)");
  }
  r.surface_adaptivity = float(o.surface_adaptivity.value_or(liquid::SurfaceSettings{}.adaptivity));
}

}  // namespace

RunSettings settle(const CaptureOptions& o, int max_steps_per_frame) {
  if (o.scene.empty()) throw UsageError("a scene is required: a JSON file, or a name in assets/scenes/");
  RunSettings r;
  const fs::path scene_path = resolve_scene(o.scene);
  std::vector<liquid::SceneOverride> overrides;
  for (const std::string& text : o.set) {
    try {
      overrides.push_back(liquid::parse_scene_override(text));
    } catch (const liquid::ArgumentError& e) {
      throw UsageError(e.what());
    }
  }
  // Recorded absolute, so a --resume from another directory finds the scene, and the files it names
  // relative to its folder (a mesh obstacle's "file").
  r.scene_source = fs::absolute(scene_path).lexically_normal().string();
  r.scene_document = liquid::scene_document(scene_path, overrides);
  r.overrides = o.set;
  const liquid::Scene scene = liquid::parse_scene(r.scene_document, r.scene_label());

  try {
    if (o.end && o.frames) throw UsageError("--end and --frames both set the last frame: give one");
    r.plan.start = o.start;
    r.plan.end = o.end ? *o.end : o.start + o.frames.value_or(60) - 1;
    if (r.plan.end < r.plan.start)
      throw UsageError("--end " + std::to_string(r.plan.end) + " is before --start " + std::to_string(r.plan.start));
    r.plan.time_step = liquid::scene_time_step(scene);
    r.plan.steps_per_frame =
        steps_per_frame(o.steps_per_frame, o.fps, r.plan.time_step, scene.substeps, max_steps_per_frame);
    if (o.fps > 0.0 && o.steps_per_frame == 0) {  // exactly o.fps frames per simulated second
      r.plan.fps = o.fps;
      r.plan.time_step = 1.0 / (o.fps * r.plan.steps_per_frame);
    }

    const fs::path out(o.out);
    if (has_frame_field(out.filename().string())) {
      r.folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
      r.frames = NamePattern::parse(out.filename().string(), "-o", ".png");
    } else if (out.extension() == ".png") {  // a frame name without its number: every frame would overwrite it
      throw UsageError("-o " + o.out + ": a frame name needs a frame number field: a run of '#', %04d or $F4 " +
                       "(e.g. " + (out.parent_path() / (out.stem().string() + "_####.png")).string() + ")");
    } else {
      r.folder = out;
      r.frames = NamePattern::parse("frame_#####.png", "-o", ".png");
    }
    if (o.export_particles || !o.particles_name.empty())
      r.particles = NamePattern::parse(o.particles_name.empty() ? "particles_#####.ply" : o.particles_name,
                                       "--particles-name", ".ply");
    if (o.export_volume || !o.volume_name.empty())
      r.volumes = NamePattern::parse(o.volume_name.empty() ? "volume_#####.vdb" : o.volume_name, "--volume-name", ".vdb");
    settle_surface(o, r);
    if (o.export_whitewater || !o.whitewater_name.empty())
      r.whitewater = NamePattern::parse(o.whitewater_name.empty() ? "whitewater_#####.ply" : o.whitewater_name,
                                        "--whitewater-name", ".ply");
    std::set<std::string> names{r.frames.text()};
    for (const auto& [pattern, flag] : r.optional_outputs())
      if (!names.insert(pattern->text()).second) throw UsageError("two outputs have the same name pattern");
  } catch (const UsageError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  r.width = o.width;
  r.height = o.height;
  r.fxaa = o.fxaa;
  r.draw_particles = o.draw_particles;
  r.camera_position = o.camera_position;
  r.camera_target = o.camera_target;
  r.fov_y_degrees = o.fov_y_degrees;
  r.checkpoint_every = o.checkpoint_every;
  // Recorded absolute, so a --resume from another directory writes the video where the run did.
  r.video = o.video.empty() ? std::string() : fs::absolute(o.video).lexically_normal().string();
  if (!r.video.empty()) {
    const std::string ext = fs::path(r.video).extension().string();
    if (ext != ".mp4" && ext != ".mkv" && ext != ".mov")
      throw UsageError("--video " + r.video + ": the name must end in .mp4, .mkv or .mov");
  }
  try {
    check_name_lengths(r);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return r;
}

void check_resume_flags(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    const std::string name = option->get_name();
    if (option->count() == 0 || name == "--resume" || name == "--validation" || name == "--3d-path") continue;
    throw UsageError("--resume continues the run recorded in its folder with the same settings; " +
                     (name == "scene" ? std::string("a scene") : name) + " cannot be given with it");
  }
}

json to_json(const RunSettings& r) {
  const auto optional_name = [](const std::optional<NamePattern>& p) { return p ? json(p->text()) : json(nullptr); };
  return {{"tool", "liquid_capture"},
          {"record_version", 1},
          {"scene_source", r.scene_source},
          {"overrides", r.overrides},
          {"scene", json::parse(r.scene_document)},
          {"frames", {{"start", r.plan.start}, {"end", r.plan.end}, {"steps_per_frame", r.plan.steps_per_frame},
                      {"time_step_s", r.plan.time_step}, {"frame_seconds", r.plan.frame_seconds()},
                      {"fps", r.plan.frames_per_second()}, {"fps_exact", r.plan.fps > 0.0}}},
          {"names", {{"frames", r.frames.text()}, {"particles", optional_name(r.particles)},
                     {"volumes", optional_name(r.volumes)}, {"surfaces", optional_name(r.surfaces)},
                     {"meshes", optional_name(r.meshes)}, {"whitewater", optional_name(r.whitewater)}}},
          {"surface", {{"voxels_per_cell", r.surface_voxels_per_cell}, {"adaptivity", r.surface_adaptivity}}},
          {"view", {{"width", r.width}, {"height", r.height}, {"fxaa", r.fxaa}, {"draw_particles", r.draw_particles},
                    {"camera_position", r.camera_position}, {"camera_target", r.camera_target},
                    {"fov_y_degrees", r.fov_y_degrees}}},
          {"checkpoint_every", r.checkpoint_every},
          {"video", r.video}};
}

RunSettings run_settings_from_json(const json& j, const fs::path& folder, const std::string& source) {
  // Each value within the range its flag takes.
  const auto number = [](const json& value, const char* name, double lo, double hi, bool integer) {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < lo || value.get<double>() > hi ||
        (integer && !value.is_number_integer()))
      throw std::runtime_error(std::string(name) + ": must be " + (integer ? "an integer" : "a number") + " in [" +
                               tools::format_cli_number(lo) + ", " + tools::format_cli_number(hi) + "], got " + value.dump());
    return value.get<double>();
  };
  const auto point = [&](const json& value, const char* name) {
    std::vector<float> p;
    if (!value.is_array() || (value.size() != 0 && value.size() != 3))
      throw std::runtime_error(std::string(name) + ": must be empty or 3 numbers, got " + value.dump());
    for (const json& x : value) p.push_back(float(number(x, name, -k_max_camera_coordinate, k_max_camera_coordinate, false)));
    return p;
  };
  try {
    if (j.at("tool") != "liquid_capture" || j.at("record_version") != 1)
      throw std::runtime_error("not a record of this version of liquid_capture");
    RunSettings r;
    r.scene_source = j.at("scene_source").get<std::string>();
    r.overrides = j.at("overrides").get<std::vector<std::string>>();
    r.scene_document = j.at("scene").dump(2);
    const json& f = j.at("frames");
    r.plan.start = int(number(f.at("start"), "frames.start", 0, k_max_frame, true));
    r.plan.end = int(number(f.at("end"), "frames.end", r.plan.start, k_max_frame, true));
    r.plan.steps_per_frame = int(number(f.at("steps_per_frame"), "frames.steps_per_frame", 1, k_max_steps_per_frame, true));
    r.plan.time_step = number(f.at("time_step_s"), "frames.time_step_s", 1e-9, 1.0, false);
    if (f.value("fps_exact", false)) r.plan.fps = number(f.at("fps"), "frames.fps", 0.001, 10000.0, false);
    r.folder = folder;
    const json& n = j.at("names");
    r.frames = NamePattern::parse(n.at("frames").get<std::string>(), "frames", ".png");
    if (!n.at("particles").is_null()) r.particles = NamePattern::parse(n.at("particles"), "particles", ".ply");
    if (!n.at("volumes").is_null()) r.volumes = NamePattern::parse(n.at("volumes"), "volumes", ".vdb");
    if (n.contains("surfaces") && !n.at("surfaces").is_null()) {  // a record from before the surface export has none
      r.surfaces = NamePattern::parse(n.at("surfaces"), "surfaces", ".vdb");
      const std::string mesh = n.at("meshes").get<std::string>();
      r.meshes = NamePattern::parse(mesh, "meshes", fs::path(mesh).extension() == ".obj" ? ".obj" : ".ply");
      const json& surface = j.at("surface");
      r.surface_voxels_per_cell = int(number(surface.at("voxels_per_cell"), "surface.voxels_per_cell", 1,
                                             liquid::k_max_surface_voxels_per_cell, true));
      r.surface_adaptivity = float(number(surface.at("adaptivity"), "surface.adaptivity", 0.0, 1.0, false));
    }
    if (n.contains("whitewater") && !n.at("whitewater").is_null())  // a record from before the whitewater export has none
      r.whitewater = NamePattern::parse(n.at("whitewater"), "whitewater", ".ply");
    const json& v = j.at("view");
    r.width = uint32_t(number(v.at("width"), "view.width", 1, k_max_pixels, true));
    r.height = uint32_t(number(v.at("height"), "view.height", 1, k_max_pixels, true));
    r.fxaa = v.at("fxaa").get<bool>();
    r.draw_particles = v.at("draw_particles").get<bool>();
    r.camera_position = point(v.at("camera_position"), "view.camera_position");
    r.camera_target = point(v.at("camera_target"), "view.camera_target");
    const json& fov = v.at("fov_y_degrees");  // 0: the scene's
    r.fov_y_degrees = fov == 0 ? 0.0f : float(number(fov, "view.fov_y_degrees", k_min_fov_degrees, k_max_fov_degrees, false));
    r.checkpoint_every = int(number(j.at("checkpoint_every"), "checkpoint_every", 0, k_max_frame, true));
    r.video = j.at("video").get<std::string>();
    check_name_lengths(r);
    return r;
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ": " + e.what());
  }
}

}  // namespace capture
