// liquid_capture: the offline frame-capture tool. Runs a scene and writes numbered PNG frames, a
// statistics table (stats.csv: the solver's diagnostics and each pass's GPU time per frame), a
// summary, and on request particles (PLY), secondary particles (whitewater PLY), grids (OpenVDB),
// the surface (a level-set VDB and a mesh), a video and checkpoints to resume from. It is a host
// like any engine: it builds its render graph through the liquid module's public API (LiquidNode,
// LiquidRenderer); only its dry run and summary read the derived setup, and its frame writer the
// secondary particles (simulation_of(node)). The pieces live in tools/liquid_capture/.
#include "engine/io/atomic_file.h"
#include "engine/vk/context.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/scene.h"
#include "liquid/scene/json_nesting.h"
#include "liquid/solver/simulation.h"
#include "tools/common/cli.h"
#include "tools/common/frame_loop.h"
#include "tools/common/grid_path_flag.h"
#include "tools/common/progress.h"
#include "tools/liquid_capture/checkpoint.h"
#include "tools/liquid_capture/dry_run.h"
#include "tools/liquid_capture/frame_writer.h"
#include "tools/liquid_capture/options.h"
#include "tools/liquid_capture/outputs.h"
#include "tools/liquid_capture/session.h"
#include "tools/liquid_capture/video.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using capture::RunSettings;
using nlohmann::json;

using capture::k_max_steps_per_frame;
constexpr int k_interrupted_exit = 130;  // 128 + SIGINT, what shells report for Ctrl-C

// Ctrl-C or SIGTERM: the frame in progress finishes, then the run stops as if it had ended there.
// The handler only records the signal; a second one kills at once (SA_RESETHAND).
volatile std::sig_atomic_t g_stop_signal = 0;
void on_stop_signal(int signal) { g_stop_signal = signal; }

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);  // a dead ffmpeg is a write error, not a silent exit
}

// One row of stats.csv.
struct FrameStats {
  int frame = 0;
  liquid::Diagnostics diagnostics;
  double wall_ms = 0.0;
  std::map<std::string, double> pass_ms;  // summed over the frame's passes of that name
  // The exports' measures: surface_ms a column with --export-surface, the whitewater's two columns
  // when the run reads the secondary particles back (RunSettings::reads_whitewater()).
  capture::FrameExports exports;
};
constexpr const char* k_surface_column = ",surface_ms";
constexpr const char* k_whitewater_columns = ",whitewater_particles,whitewater_ms";

// Each dynamic obstacle's pose, velocity, force and torque in stats.csv (2D: per metre of depth):
// the columns' names after "body<obstacle index>.", and their values.
constexpr const char* k_body_columns[] = {"x_m",      "y_m",      "z_m",      "qw",     "qx",     "qy",    "qz",
                                          "vx_m_s",   "vy_m_s",   "vz_m_s",   "wx_rad_s", "wy_rad_s", "wz_rad_s",
                                          "fx_N",     "fy_N",     "fz_N",     "tx_N_m", "ty_N_m", "tz_N_m"};
std::vector<float> body_columns(const liquid::BodyState& b) {
  const glm::vec3 &x = b.pose.center, &v = b.pose.velocity, &w = b.pose.angular_velocity;
  const glm::quat& q = b.pose.orientation;
  return {x.x, x.y, x.z, q.w, q.x, q.y, q.z, v.x, v.y, v.z, w.x, w.y, w.z,
          b.force.x, b.force.y, b.force.z, b.torque.x, b.torque.y, b.torque.z};
}

// stats.csv's header names the passes of the first written frame (every frame declares the same).
std::string stats_header(const FrameStats& first, bool surface, bool whitewater) {
  std::string header =
      "frame,step,time_s,active_particles,outside_domain,inside_obstacles,non_finite,max_density_ratio,mass_kg,"
      "kinetic_energy_J,potential_energy_J,mechanical_energy_J,time_step_s,max_speed_m_s,wall_ms";
  for (const liquid::BodyState& b : first.diagnostics.bodies)
    for (const char* column : k_body_columns) header += ",body" + std::to_string(b.obstacle) + "." + column;
  for (const auto& [name, ms] : first.pass_ms) header += ",gpu_ms." + name;
  if (surface) header += k_surface_column;
  if (whitewater) header += k_whitewater_columns;
  return header + "\n";
}

std::string stats_row(const FrameStats& row, const std::string& header) {
  const liquid::Diagnostics& d = row.diagnostics;
  std::ostringstream out;
  out.precision(9);
  out << row.frame << ',' << d.step << ',' << d.time << ',' << d.active_particles << ',' << d.outside_domain << ','
      << d.inside_obstacles << ',' << d.non_finite << ',' << d.max_density_ratio << ',' << d.mass << ','
      << d.kinetic_energy << ',' << d.potential_energy << ',' << d.mechanical_energy << ',' << d.time_step << ','
      << d.max_speed << ',' << row.wall_ms;
  for (const liquid::BodyState& b : d.bodies)
    for (float value : body_columns(b)) out << ',' << value;
  std::istringstream columns(header);
  std::string column;
  while (std::getline(columns, column, ','))
    if (column.rfind("gpu_ms.", 0) == 0) {
      if (!column.empty() && column.back() == '\n') column.pop_back();
      const auto it = row.pass_ms.find(column.substr(7));
      out << ',' << (it == row.pass_ms.end() ? 0.0 : it->second);
    }
  if (header.find(k_surface_column) != std::string::npos) out << ',' << row.exports.surface_ms;
  if (header.find(k_whitewater_columns) != std::string::npos)
    out << ',' << row.exports.whitewater_particles << ',' << row.exports.whitewater_ms;
  out << "\n";
  return out.str();
}

liquid::CameraView camera_from(const RunSettings& s, const liquid::LiquidNode& node) {
  liquid::CameraView camera = liquid::default_camera(node);
  if (!s.camera_position.empty()) camera.position = {s.camera_position[0], s.camera_position[1], s.camera_position[2]};
  if (!s.camera_target.empty()) camera.target = {s.camera_target[0], s.camera_target[1], s.camera_target[2]};
  if (s.fov_y_degrees > 0.0f) camera.fov_y_degrees = s.fov_y_degrees;
  if (glm::length(camera.position - camera.target) < 1e-6f)
    throw capture::UsageError("--camera-position and --camera-target must differ");
  return camera;
}

// The run's record, sized before it is read and its nesting counted before it is parsed, so an
// oversized, endless (a link to /dev/zero) or deeply nested file is refused at once.
std::string read_record(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error))
    throw std::runtime_error(path.parent_path().string() + ": not a capture folder (no " + path.filename().string() + ")");
  const std::string text = capture::read_sized_file(path, capture::k_max_record_bytes, "capture's record");
  if (liquid::json_nesting_depth(text) > capture::k_max_record_nesting)
    throw std::runtime_error(path.string() + ": not a capture's record (nested deeper than " +
                             std::to_string(capture::k_max_record_nesting) + " levels)");
  return text;
}

// A path as the file system will resolve it, for comparing two: absolute, links resolved as far as
// they exist, no trailing separator.
fs::path resolved(const fs::path& path) {
  std::error_code error;
  fs::path p = fs::weakly_canonical(fs::absolute(path), error);
  if (error) p = fs::absolute(path).lexically_normal();
  return p.has_filename() ? p : p.parent_path();
}

// Before --video, the checks that need no device: ffmpeg installed, the file free and not the
// output folder, its folder there (or the output folder, which the run creates).
void check_video(const RunSettings& s, bool overwrite) {
  if (s.video.empty()) return;
  const fs::path path(s.video);
  const fs::path out = resolved(s.folder);
  if (resolved(path) == out)
    throw capture::UsageError("--video " + s.video + ": is the output folder; name a file (e.g. " +
                              (out / "liquid.mp4").string() + ")");
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (resolved(folder) != out && (!fs::is_directory(folder) || !engine::io::folder_is_writable(folder)))
    throw std::runtime_error("--video " + s.video + ": " + folder.string() + " is not a writable folder");
  if (fs::is_directory(path)) throw std::runtime_error("--video " + s.video + ": is a folder, not a video file");
  if (fs::exists(path) && !overwrite) throw std::runtime_error(s.video + ": exists; --overwrite replaces it");
  if (!capture::find_on_path("ffmpeg"))
    throw std::runtime_error("--video needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg)");
}

int run(const capture::CaptureOptions& options, const CLI::App& app) {
  const auto started = std::chrono::steady_clock::now();
  install_stop_handlers();
  const bool resuming = !options.resume.empty();
  RunSettings settings;
  std::string record_text;
  capture::CaptureCheckpoint checkpoint;
  if (resuming) {
    capture::check_resume_flags(app);
    const fs::path folder(options.resume);
    record_text = read_record(folder / capture::k_record_name);
    const std::string record_name = (folder / capture::k_record_name).string();
    const json record = json::parse(record_text, nullptr, /*allow_exceptions=*/false);
    if (record.is_discarded()) throw std::runtime_error(record_name + ": not valid JSON (not a capture's record)");
    settings = capture::run_settings_from_json(record, folder, record_name);
    checkpoint = capture::load_checkpoint(folder / capture::k_checkpoint_name);
    if (checkpoint.settings_hash != capture::fingerprint(record_text))
      throw std::runtime_error((folder / capture::k_checkpoint_name).string() + ": belongs to another run than " +
                               (folder / capture::k_record_name).string());
    capture::check_against_plan(checkpoint, settings.plan, (folder / capture::k_checkpoint_name).string());
  } else {
    const tools::SetupStage stage("liquid_capture", "reading the scene and its meshes");
    settings = capture::settle(options, k_max_steps_per_frame);
    record_text = capture::to_json(settings).dump(2) + "\n";
  }
  const liquid::Scene scene = [&] {
    const tools::SetupStage stage("liquid_capture", "reading the scene and its meshes");
    return liquid::parse_scene(settings.scene_document, settings.scene_label());
  }();
  for (const auto& [requested, flag] :
       {std::pair{settings.volumes.has_value(), "--export-volume"}, {settings.surfaces.has_value(), "--export-surface"}})
    if (requested && !capture::volume_export_available())
      throw std::runtime_error(std::string(flag) + ": this build has no OpenVDB (install libopenvdb-dev and "
                               "libboost-iostreams-dev, then configure again)");
  if (settings.surfaces && scene.dimension != 3)
    throw capture::UsageError("--export-surface: " + settings.scene_label() + " is a " +
                              std::to_string(scene.dimension) + "D scene; the surface export needs a 3D one");
  if (settings.whitewater && !scene.whitewater)
    throw capture::UsageError("--export-whitewater: " + settings.scene_label() + " has no \"whitewater\", so no "
                              "spray, foam or bubbles to export (add \"whitewater\": {}, docs/whitewater.md)");
  check_video(settings, options.overwrite || resuming);
  // A video already there (a replaced run's, or the one a resumed run made) is replaced only by a
  // run that ends well: a failed one removes its own instead.
  const bool video_existed = !settings.video.empty() && fs::exists(settings.video);
  using Mode = capture::RunFolder::Mode;
  capture::RunFolder folder(settings, options.dry_run ? Mode::DryRun
                                      : resuming      ? Mode::Resume
                                      : options.overwrite ? Mode::Overwrite
                                                          : Mode::New);

  std::optional<tools::SetupStage> stage(std::in_place, "liquid_capture",
                                        "setting up the simulation (particles, obstacles, pipelines)");
  engine::vk::Context context(engine::vk::ContextOptions{.validation = options.validation});
  const capture::FramePlan& plan = settings.plan;
  liquid::LiquidNode node(context, scene,
                          liquid::LiquidOptions{.frames_in_flight = 1,
                                                .max_steps_per_frame = plan.steps_per_frame,
                                                .grid_path = tools::grid_path_from_flag(options.grid_path),
                                                .log = tools::stdout_log()});
  liquid::LiquidRenderer renderer(
      context, node,
      liquid::RenderSettings{.width = settings.width, .height = settings.height, .fxaa = settings.fxaa,
                             .draw_particles = settings.draw_particles});
  const liquid::CameraView camera = camera_from(settings, node);
  stage.reset();
  // --fps: the step shortened so a whole number of them makes exactly one frame (a checkpoint being
  // resumed carries it too). Adaptive steps fit each frame themselves (steps_for_frame).
  if (!scene.adaptive_time_step && plan.time_step < node.time_step()) node.set_time_step(plan.time_step);
  tools::FrameLoop loop(context);
  if (options.dry_run) {
    capture::dry_run(settings, context, node, renderer, camera, loop, started);
    tools::fail_on_validation_messages(context.validation_message_count());
    return 0;
  }

  // Everything that can reject the input has run: only now are files touched.
  capture::StatsTable stats(settings.folder / capture::k_stats_name);
  int first_frame = plan.start == 0 ? 0 : 1;  // frame 0, the initial state, has nothing to run unless written
  if (resuming) {
    node.restore_checkpoint(checkpoint.node);
    for (const fs::path& file : capture::run_files(settings))
      if (file.extension() == ".partial") fs::remove(file);  // what the interrupted run was writing
    stats.restore(checkpoint.stats_csv);
    first_frame = checkpoint.frame + 1;
  } else {
    folder.set_old_files_aside();
    engine::io::write_file_atomically(settings.folder / capture::k_record_name, record_text);
  }
  const capture::FrameWriter writer(settings, context, settings.folder, scene.name);
  std::unique_ptr<capture::VideoEncoder> video;
  if (!settings.video.empty()) {
    video = std::make_unique<capture::VideoEncoder>(settings.video, settings.width, settings.height,
                                                    plan.frames_per_second());
    for (int f = plan.start; f < first_frame && f <= plan.end; ++f)  // a resumed run re-encodes the frames kept
      video->add(engine::vk::read_png(settings.folder / settings.frames.name(f)));
  }

  const liquid::SimulationSetup& s = simulation_of(node).setup();
  std::printf("liquid_capture: %s, %dD, %d particles (capacity %d), grid %dx%dx%d, dt %.3g s, %d steps per frame "
              "(%.1f simulated frames/s), frames %d to %d, %ux%u, device %s%s\n",
              scene.name.c_str(), s.dimension, s.initial_particles, s.capacity, s.grid_cells.x, s.grid_cells.y,
              s.grid_cells.z, plan.time_step, plan.steps_per_frame, plan.frames_per_second(), plan.start, plan.end,
              settings.width, settings.height, context.device_name().c_str(),
              resuming ? (", resumed after frame " + std::to_string(checkpoint.frame)).c_str() : "");
  std::fflush(stdout);

  std::string header = stats.text().substr(0, stats.text().find('\n') + 1);
  int last_done = first_frame - 1;
  // The exports' times summed over the frames this process wrote, for the run's last line.
  double surface_ms_total = 0.0, whitewater_ms_total = 0.0;
  const bool reads_whitewater = settings.reads_whitewater(scene.whitewater.has_value());
  // Ends the run where it stands: stats.csv and summary.json for the frames written, the video closed.
  const auto conclude = [&](const std::string& status) {
    stats.finish();
    std::string video_status = video ? "finished" : "";
    try {
      if (video && status.rfind("failed", 0) == 0 && video_existed) {
        video.reset();  // stops ffmpeg and removes its partial file
        video_status = "not written: the run failed, and " + settings.video + " is kept";
      }
      if (video) video->finish();
    } catch (const std::exception& error) {
      // The summary says so, then the run fails: with no replaced run set aside its frames, table
      // and summary stand; with one, they are removed and the replaced run (and its video) come back.
      video_status = std::string("failed: ") + error.what();
    }
    json facts = {{"status", status},
                        {"scene", scene.name},
                        {"scene_source", settings.scene_source},
                        {"device", context.device_name()},
                        {"frames_planned", {plan.start, plan.end}},
                        {"last_frame_simulated", last_done},
                        {"steps_per_frame", plan.steps_per_frame},
                        {"frame_seconds", plan.frame_seconds()},
                        {"resumed_after_frame", resuming ? json(checkpoint.frame) : json(nullptr)},
                        {"run_wall_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()}};
    if (!video_status.empty()) facts["video"] = video_status;
    engine::io::write_file_atomically(settings.folder / capture::k_summary_name, capture::summary_json(stats.text(), facts));
    if (video_status.rfind("failed", 0) == 0) throw std::runtime_error("--video: " + video_status);
  };

  tools::Progress progress(plan.end - first_frame + 1);
  try {
    for (int frame = first_frame; frame <= plan.end && !g_stop_signal; ++frame) {
      const bool written = frame >= plan.start;
      // Frame f is the state after f frames of steps: frame 0 takes none.
      const int steps = frame == 0 ? 0 : capture::steps_for_frame(node, plan.steps_per_frame, plan.frame_seconds());
      const capture::FrameResult result = capture::run_frame(loop, node, written ? &renderer : nullptr, camera, steps,
                                                             frame == 0 || settings.exports_grids());
      const liquid::ParticleSnapshot particles = node.read_particles();
      FrameStats row{frame, node.diagnose(particles), result.time.wall_ms, {}};  // throws on an unstable state
      node.adapt_time_step(row.diagnostics);
      if (written) {
        for (const auto& t : result.time.passes) row.pass_ms[t.name] += t.milliseconds;
        row.exports = writer.write(frame, node, particles, *result.image);
        surface_ms_total += row.exports.surface_ms;
        whitewater_ms_total += row.exports.whitewater_ms;
        if (header.empty()) header = stats_header(row, settings.surfaces.has_value(), reads_whitewater);
        stats.append(header, stats_row(row, header));
        folder.wrote_output();
      }
      // The frame's files and row are complete: a video failure below keeps them, unless a replaced
      // run is put back.
      last_done = frame;
      if (written && video) video->add(*result.image);
      if (settings.checkpoint_every > 0 && frame > 0 && frame % settings.checkpoint_every == 0) {
        capture::save_checkpoint(settings.folder / capture::k_checkpoint_name,
                                 {frame, capture::fingerprint(record_text), node.save_checkpoint(), stats.text()});
        folder.wrote_output();
      }
      progress.update(frame - first_frame + 1, steps / std::max(row.wall_ms * 1e-3, 1e-9), "steps");
    }
    // Before the run concludes as finished (which renames its video over an existing one): a run
    // with validation messages fails like any other, keeping the replaced run and its video.
    if (!g_stop_signal) tools::fail_on_validation_messages(context.validation_message_count());
  } catch (const std::exception& error) {
    progress.interrupt();  // the error message starts on its own line
    try {
      // With a replaced run to put back, the new run's files are removed: no summary to write.
      if (last_done >= plan.start && !folder.puts_back_on_failure()) conclude(std::string("failed: ") + error.what());
    } catch (...) {
    }
    throw;
  }
  if (g_stop_signal) {
    progress.interrupt();
    // The user chose to stop here: what was written is the run, as if it had ended there, and
    // replaces the run set aside. Stopped before writing anything, the run is given up like a failed one.
    if (last_done >= plan.start || resuming) {
      conclude("interrupted");
      folder.ended_well();
    }
    const char* name = g_stop_signal == SIGTERM ? "SIGTERM" : "SIGINT";
    std::fprintf(stderr, "liquid_capture: interrupted (%s) after frame %d; %s\n", name, last_done,
                 last_done >= plan.start ? ("files, stats.csv and summary.json cover frames " + std::to_string(plan.start) +
                                            " to " + std::to_string(last_done)).c_str()
                                         : "no frame was written");
    return k_interrupted_exit;
  }
  conclude("finished");
  folder.ended_well();
  std::printf("liquid_capture: wrote frames %d to %d to %s", plan.start, plan.end, settings.folder.string().c_str());
  const int written_here = plan.end - std::max(first_frame, plan.start) + 1;
  if (settings.surfaces && written_here > 0)
    std::printf("; the surface export took %.1f ms a frame", surface_ms_total / written_here);
  if (reads_whitewater && written_here > 0)
    std::printf("; the whitewater export took %.1f ms a frame", whitewater_ms_total / written_here);
  std::printf("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a liquid scene and writes numbered PNG frames, per-frame statistics and, optionally, particles, "
               "volumes, a video and checkpoints"};
  capture::CaptureOptions options;
  capture::add_options(app, options);
  return tools::run_main(app, argc, argv, "liquid_capture", [&] {
    try {
      return run(options, app);
    } catch (const capture::UsageError& error) {
      tools::print_error("liquid_capture", error.what());
      return 2;
    }
  });
}
