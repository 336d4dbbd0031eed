// liquid_capture: the offline frame-capture tool. Runs a scene and writes numbered PNG frames, a
// statistics table (stats.csv: the solver's diagnostics and each pass's GPU time per frame) and,
// on request, the particles of every frame as binary PLY. It is a host like any engine: it builds
// its render graph through the liquid module's public API (LiquidNode, LiquidRenderer) only.
#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/io/atomic_file.h"
#include "engine/vk/context.h"
#include "engine/vk/png.h"
#include "liquid/export/ply.h"
#include "liquid/node.h"
#include "liquid/render/renderer.h"
#include "liquid/scene.h"
#include "tools/cli.h"
#include "tools/frame_loop.h"
#include "tools/progress.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct CaptureOptions {
  std::filesystem::path scene;
  std::filesystem::path out_dir = "frames";
  int frames = 60;
  double fps = 0.0;  // 0: the scene's substeps per frame
  int steps_per_frame = 0;
  uint32_t width = 1024, height = 768;
  std::vector<float> camera_position, camera_target;
  float fov_y_degrees = 0.0f;
  bool fxaa = true;
  bool draw_particles = false;
  bool export_particles = false;
  bool validation = false;
};

// One row of stats.csv.
struct FrameStats {
  int frame = 0;
  liquid::Diagnostics diagnostics;
  double wall_ms = 0.0;
  std::map<std::string, double> pass_ms;  // summed over the frame's passes of that name
};

// stats.csv: a header naming the passes of the first frame (every frame declares the same ones),
// then one row per frame.
std::string stats_header(const FrameStats& first) {
  std::string header =
      "frame,step,time_s,active_particles,outside_domain,inside_obstacles,non_finite,max_density_ratio,mass_kg,"
      "kinetic_energy_J,potential_energy_J,mechanical_energy_J,time_step_s,max_speed_m_s,wall_ms";
  for (const auto& [name, ms] : first.pass_ms) header += ",gpu_ms." + name;
  return header + "\n";
}

std::string stats_row(const FrameStats& row, const FrameStats& first) {
  const liquid::Diagnostics& d = row.diagnostics;
  std::ostringstream out;
  out << row.frame << ',' << d.step << ',' << d.time << ',' << d.active_particles << ',' << d.outside_domain << ','
      << d.inside_obstacles << ',' << d.non_finite << ',' << d.max_density_ratio << ',' << d.mass << ','
      << d.kinetic_energy << ',' << d.potential_energy << ',' << d.mechanical_energy << ',' << d.time_step << ','
      << d.max_speed << ',' << row.wall_ms;
  for (const auto& [name, unused] : first.pass_ms) {
    const auto it = row.pass_ms.find(name);
    out << ',' << (it == row.pass_ms.end() ? 0.0 : it->second);
  }
  out << "\n";
  return out.str();
}

// Appends rows to "<path>.partial", flushed after each frame so a long run can be watched, and
// renames it to <path> once the run has finished: an interrupted run leaves only the .partial file.
class StatsFile {
 public:
  explicit StatsFile(std::filesystem::path path) : path_(std::move(path)) {}
  void append(const std::string& text) {
    if (!file_.is_open()) {
      file_.open(partial(), std::ios::trunc);
      if (!file_) throw std::runtime_error(partial().string() + ": cannot write");
    }
    file_ << text;
    file_.flush();
    if (!file_) throw std::runtime_error(partial().string() + ": write failed (disk full?)");
  }
  void finish() {
    file_.close();
    std::filesystem::rename(partial(), path_);
  }

 private:
  std::filesystem::path partial() const { return std::filesystem::path(path_.string() + ".partial"); }
  std::filesystem::path path_;
  std::ofstream file_;
};

std::string numbered(const char* stem, int frame, const char* extension) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%05d.%s", stem, frame, extension);
  return name;
}

liquid::CameraView camera_from(const CaptureOptions& options, const liquid::LiquidNode& node) {
  liquid::CameraView camera = liquid::default_camera(node.scene(), node.setup());
  if (!options.camera_position.empty())
    camera.position = {options.camera_position[0], options.camera_position[1], options.camera_position[2]};
  if (!options.camera_target.empty())
    camera.target = {options.camera_target[0], options.camera_target[1], options.camera_target[2]};
  if (options.fov_y_degrees > 0.0f) camera.fov_y_degrees = options.fov_y_degrees;
  if (glm::length(camera.position - camera.target) < 1e-6f)
    throw std::invalid_argument("--camera-position and --camera-target must differ");
  return camera;
}

constexpr int k_max_steps_per_frame = 100000;

int steps_per_frame(const CaptureOptions& options, const liquid::Scene& scene) {
  if (options.steps_per_frame > 0) return options.steps_per_frame;
  if (options.fps <= 0.0) return scene.substeps;
  const double steps = std::round(1.0 / (options.fps * scene.time_step));
  if (steps > k_max_steps_per_frame)
    throw std::invalid_argument("--fps " + std::to_string(options.fps) + " needs " + std::to_string(steps) +
                                " steps of " + std::to_string(scene.time_step) + " s per frame, more than " +
                                std::to_string(k_max_steps_per_frame));
  return std::max(1, int(steps));
}

int run(const CaptureOptions& options) {
  const liquid::Scene scene = liquid::load_scene(options.scene);
  engine::vk::Context context(engine::vk::ContextOptions{.validation = options.validation});
  const int steps = steps_per_frame(options, scene);
  liquid::LiquidNode node(context, scene, liquid::LiquidOptions{.frames_in_flight = 1, .max_steps_per_frame = steps});
  const liquid::RenderSettings settings{.width = options.width,
                                        .height = options.height,
                                        .fxaa = options.fxaa,
                                        .draw_particles = options.draw_particles};
  liquid::LiquidRenderer renderer(context, node, settings);
  const liquid::CameraView camera = camera_from(options, node);
  // Everything that can reject the input has run: only now is the output folder touched.
  engine::io::ensure_writable_folder(options.out_dir);

  const liquid::SimulationSetup& s = node.setup();
  std::printf("liquid_capture: %s, %dD, %d particles (capacity %d), grid %dx%dx%d, dt %.3g s, %d steps per frame "
              "(%.1f simulated frames/s), %ux%u, device %s\n",
              scene.name.c_str(), s.dimension, s.initial_particles, s.capacity, s.grid_cells.x, s.grid_cells.y,
              s.grid_cells.z, scene.time_step, steps, 1.0 / (steps * scene.time_step), options.width,
              options.height, context.device_name().c_str());

  tools::FrameLoop loop(context);
  StatsFile stats(options.out_dir / "stats.csv");
  FrameStats first;
  tools::Progress progress(options.frames);
  // Every frame advances the simulation by `steps` steps, then draws the state it reached (the
  // density the raymarch reads comes from the last step's grid pass).
  for (int frame = 0; frame < options.frames; ++frame) {
    try {
      engine::graph::Readback readback;
      const tools::FrameTime time = loop.run([&](engine::graph::RenderGraph& graph) {
        const liquid::LiquidImages images = node.add_to(graph, steps);
        const liquid::RenderOutputs rendered = renderer.add_to(graph, images, camera);
        readback = engine::graph::add_readback(graph, rendered.final, "capture.readback");
      });
      FrameStats row{frame, {}, time.wall_ms, {}};
      for (const auto& t : time.passes) row.pass_ms[t.name] += t.milliseconds;

      const liquid::ParticleSnapshot particles = node.read_particles();
      row.diagnostics = node.diagnose(particles);  // throws SimulationError on an unstable state
      engine::vk::write_png(options.out_dir / numbered("frame", frame, "png"), readback.rgba8());
      if (options.export_particles) liquid::write_ply(options.out_dir / numbered("particles", frame, "ply"), particles);
      if (frame == 0) {
        first = row;
        stats.append(stats_header(first));
      }
      stats.append(stats_row(row, first));
      progress.update(frame + 1, steps / std::max(row.wall_ms * 1e-3, 1e-9), "steps");
    } catch (...) {
      progress.interrupt();  // the error message starts on its own line
      throw;
    }
  }
  stats.finish();
  std::printf("liquid_capture: wrote %d frames to %s\n", options.frames, options.out_dir.string().c_str());
  tools::fail_on_validation_messages(context.validation_message_count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a liquid scene and writes numbered PNG frames, per-frame statistics and, optionally, particles"};
  CaptureOptions options;
  app.add_option("scene", options.scene, "scene JSON file")->required();
  app.add_option("-o,--out", options.out_dir, "output folder (frame_NNNNN.png, stats.csv, particles_NNNNN.ply)")
      ->take_last();
  app.add_option("-n,--frames", options.frames, "frames to write")->check(CLI::Range(1, 1000000))->take_last();
  app.add_option("--fps", options.fps, "simulated frames per second (steps per frame = 1 / (fps dt)); "
                                       "default: the scene's substeps per frame")
      ->check(CLI::Range(0.001, 10000.0));
  app.add_option("--steps-per-frame", options.steps_per_frame, "simulation steps per frame (overrides --fps)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--width", options.width, "frame width in pixels")->check(CLI::Range(1u, 65536u));
  app.add_option("--height", options.height, "frame height in pixels")->check(CLI::Range(1u, 65536u));
  app.add_option("--camera-position", options.camera_position, "camera position x,y,z (m); default: the scene's")
      ->expected(3)
      ->delimiter(',');
  app.add_option("--camera-target", options.camera_target, "point the camera looks at x,y,z (m)")
      ->expected(3)
      ->delimiter(',');
  app.add_option("--fov", options.fov_y_degrees, "vertical field of view (degrees)")->check(CLI::Range(1.0f, 170.0f));
  app.add_flag("!--no-fxaa", options.fxaa, "skip the FXAA pass");
  app.add_flag("--draw-particles", options.draw_particles, "2D views: draw the particles as points over the liquid");
  app.add_flag("--export-particles", options.export_particles, "write particles_NNNNN.ply (binary PLY) per frame");
  app.add_flag("--validation", options.validation, "enable the Vulkan validation layer; any message fails the run");
  return tools::run_main(app, argc, argv, "liquid_capture", [&] { return run(options); });
}
