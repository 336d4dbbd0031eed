// --report PATH: the final state as JSON, for the tests (what the node read back, not what was
// drawn): frames, steps, the swapchain, the diagnostics with the centre of mass, the obstacles'
// centres, the last brush position, the camera, where the panel was last drawn, the overlay's
// lines in the last frame and the validation message count.
#include "tools/liquid_viewer/viewer.h"

#include "liquid/analysis/diagnostics.h"
#include "liquid/solver/simulation.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace viewer {
namespace {

nlohmann::json vec(glm::vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace

void Viewer::write_report(const std::filesystem::path& path) {
  liquid::LiquidNode& node = session_->node();
  nlohmann::json r;
  r["scene"] = session_->path().string();
  r["frames"] = drawn_frames_;
  r["steps"] = node.step_count();
  r["time"] = node.time();
  if (node.dimension() == 3) r["grid_path"] = liquid::grid_path_name(simulation_of(node).grid_layout().path);
  r["width"] = swapchain_->extent().width;
  r["height"] = swapchain_->extent().height;
  r["swapchain_recreations"] = swapchain_->recreations();
  r["present_mode"] = present_mode_name(swapchain_->present_mode());
  r["validation_messages"] = context_->validation_message_count();
  r["fps"] = stats_.fps;  // the panel's, over the last half second
  // Over the whole run after the first frame (pipelines and the first upload excluded).
  if (drawn_frames_ > 1 && last_frame_time_ > first_frame_time_)
    r["average_fps"] = (drawn_frames_ - 1) / (last_frame_time_ - first_frame_time_);
  r["scene_error"] = stats_.scene_error;
  r["paused"] = settings_.paused;
  r["stability_error"] = stats_.simulation_error;  // what paused the run, if the check did
  if (last_brush_) r["last_brush"] = vec(*last_brush_);
  const liquid::CameraView camera = session_->camera_view();
  r["camera"] = {{"position", vec(camera.position)}, {"target", vec(camera.target)},
                 {"fov_y_degrees", camera.fov_y_degrees}};
  r["panel_shown"] = settings_.panel;
  if (panel_rect_) {
    const PanelRect& p = *panel_rect_;
    r["panel"] = {{"x", p.x}, {"y", p.y}, {"width", p.width}, {"height", p.height}, {"collapsed", p.collapsed},
                  {"message_width", p.message_width}, {"message_height", p.message_height}};
  }
  r["overlay"] = overlay_lines_;
  nlohmann::json passes = nlohmann::json::object();  // GPU ms of the last timed frame, by pass
  for (const auto& p : stats_.passes) passes[p.name] = p.milliseconds;
  r["gpu_ms"] = passes;
  nlohmann::json obstacles = nlohmann::json::array();
  for (const auto& pose : node.obstacle_poses(node.time())) obstacles.push_back(vec(pose.center));
  r["obstacles"] = obstacles;
  try {
    const liquid::Diagnostics d = node.diagnose();
    r["diagnostics"] = {{"active_particles", d.active_particles}, {"outside_domain", d.outside_domain},
                        {"inside_obstacles", d.inside_obstacles}, {"non_finite", d.non_finite},
                        {"max_density_ratio", d.max_density_ratio}, {"kinetic_energy", d.kinetic_energy},
                        {"center_of_mass", vec(d.center_of_mass)}};
    nlohmann::json bodies = nlohmann::json::array();
    for (const liquid::BodyState& b : d.bodies)
      bodies.push_back({{"obstacle", b.obstacle}, {"center", vec(b.pose.center)}, {"velocity", vec(b.pose.velocity)},
                        {"angular_velocity", vec(b.pose.angular_velocity)}, {"force", vec(b.force)},
                        {"torque", vec(b.torque)}});
    r["diagnostics"]["bodies"] = bodies;
  } catch (const liquid::SimulationError& error) {
    r["simulation_error"] = error.what();
  }
  std::ofstream out(path);
  out << r.dump(2) << "\n";
  if (!out) throw std::runtime_error(path.string() + ": cannot write the report");
}

}  // namespace viewer
