#include "tools/liquid_viewer/panel.h"

#include "liquid/node.h"
#include "liquid/physics/time_step.h"
#include "liquid/solver/simulation.h"

#include <imgui.h>

#include <exception>

namespace viewer {
namespace {

void live_parameters(liquid::LiquidNode& node) {
  liquid::LiquidNode::RuntimeParameters p = node.runtime_parameters();
  const liquid::SimulationSetup& setup = node.simulation().setup();
  // Every value the sliders offer runs stable at the present step (liquid/physics/time_step.h);
  // AlwaysClamp holds Ctrl+click typing to the range too.
  const liquid::RuntimeParameterRange range =
      liquid::runtime_parameter_range(setup, node.time_step(), p.stiffness, p.gravity);
  const ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
  const float gmax = range.max_gravity;
  bool changed = false;
  if (node.dimension() == 2) {
    float g[2] = {p.gravity.x, p.gravity.y};
    changed |= ImGui::SliderFloat2("gravity (m/s^2)", g, -gmax, gmax, "%.2f", clamp);
    p.gravity = {g[0], g[1], 0.0f};
  } else {
    changed |= ImGui::SliderFloat3("gravity (m/s^2)", &p.gravity.x, -gmax, gmax, "%.2f", clamp);
  }
  // The range bounds |g|, not each component: a diagonal past it is shortened to it.
  if (const float length = glm::length(p.gravity); length > gmax) p.gravity *= gmax / length;
  const bool per_second = setup.pic_ratio_reference_step > 0.0f;
  changed |= ImGui::SliderFloat(per_second ? "PIC ratio (per reference step)" : "PIC ratio", &p.pic_ratio,
                                range.min_pic_ratio, range.max_pic_ratio, "%.3f", clamp);
  changed |= ImGui::SliderFloat("stiffness k", &p.stiffness, range.min_stiffness, range.max_stiffness, "%.1f",
                                ImGuiSliderFlags_Logarithmic | clamp);
  if (changed) node.set_runtime_parameters(p);
}

}  // namespace

PanelRequest draw_panel(Settings& s, MouseTools& mouse, liquid::LiquidNode& node, const Stats& stats,
                        const std::vector<std::filesystem::path>& scenes, const std::filesystem::path& current) {
  PanelRequest request;
  // Top right: the scenes' liquid starts on the left.
  ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("liquid_viewer", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%.1f fps (%.1f ms), %ux%u, %s", stats.fps, stats.frame_ms, stats.width, stats.height,
              stats.present_mode.c_str());
  ImGui::Text("t = %.3f s, step %d, %d steps this frame", node.time(), node.step_count(), stats.steps_this_frame);
  if (s.pacing == Pacing::WallTime) ImGui::Text("lag behind wall time: %.3f s", stats.lag);
  if (!stats.scene_error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "reload failed: %s", stats.scene_error.c_str());
  if (!stats.simulation_error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", stats.simulation_error.c_str());
  if (!stats.status.empty()) ImGui::TextWrapped("%s", stats.status.c_str());

  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::string name = current.filename().string();
    if (ImGui::BeginCombo("scene", name.c_str())) {
      for (const auto& path : scenes)
        if (ImGui::Selectable(path.filename().string().c_str(), path == current)) request.open_scene = path;
      ImGui::EndCombo();
    }
    if (ImGui::Button(s.paused ? "resume" : "pause")) s.paused = !s.paused;
    ImGui::SameLine();
    if (ImGui::Button("step")) s.paused = s.step_once = true;
    ImGui::SameLine();
    if (ImGui::Button("reset")) request.action = Action::Reset;
    ImGui::SameLine();
    if (ImGui::Button("reload")) request.action = Action::Reload;
    ImGui::SameLine();
    if (ImGui::Button("shot")) request.action = Action::Screenshot;
    ImGui::Checkbox("FXAA", &s.fxaa);
    if (node.dimension() == 2) {
      ImGui::SameLine();
      ImGui::Checkbox("particles", &s.particles);
    }
  }
  if (ImGui::CollapsingHeader("Pacing and parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    int pacing = int(s.pacing);
    ImGui::RadioButton("steps per frame", &pacing, int(Pacing::FixedSteps));
    ImGui::SameLine();
    ImGui::RadioButton("wall time", &pacing, int(Pacing::WallTime));
    s.pacing = Pacing(pacing);
    if (s.pacing == Pacing::FixedSteps) ImGui::SliderInt("steps/frame", &s.steps_per_frame, 1, s.max_steps_per_frame);
    else ImGui::Text("at most %d steps per frame", s.max_steps_per_frame);
    live_parameters(node);
    ImGui::SliderFloat("brush strength (1/s)", &mouse.brush_strength, 0.0f, 200.0f);
    ImGui::SliderFloat("brush radius (m)", &mouse.brush_radius, 0.005f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
  }
  if (ImGui::CollapsingHeader("Diagnostics", ImGuiTreeNodeFlags_DefaultOpen) && stats.diagnostics) {
    const liquid::Diagnostics& d = *stats.diagnostics;
    ImGui::Text("particles %d (outside %d, in obstacles %d)", d.active_particles, d.outside_domain, d.inside_obstacles);
    ImGui::Text("max rho/rho0 %.3f, max speed %.2f m/s", d.max_density_ratio, d.max_speed);
    ImGui::Text("kinetic %.4g J, mechanical %.4g J", d.kinetic_energy, d.mechanical_energy);
  }
  if (ImGui::CollapsingHeader("GPU time per pass (ms)", ImGuiTreeNodeFlags_DefaultOpen)) {
    double total = 0.0;
    for (const auto& p : stats.passes) {
      ImGui::Text("%-28s %8.3f", p.name.c_str(), p.milliseconds);
      total += p.milliseconds;
    }
    ImGui::Text("%-28s %8.3f", "total", total);
  }
  if (ImGui::CollapsingHeader("Keys")) ImGui::TextUnformatted(key_help());
  ImGui::End();
  return request;
}

}  // namespace viewer
