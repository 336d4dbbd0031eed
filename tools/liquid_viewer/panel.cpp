#include "tools/liquid_viewer/panel.h"

#include "liquid/node.h"
#include "liquid/physics/time_step.h"
#include "liquid/solver/simulation.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace viewer {
namespace {

void live_parameters(liquid::LiquidNode& node) {
  liquid::LiquidNode::RuntimeParameters p = node.runtime_parameters();
  // Every value the sliders offer runs stable at the present step; AlwaysClamp holds Ctrl+click
  // typing to the range too.
  const liquid::RuntimeParameterRange range = node.runtime_parameter_range(p);
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
  const bool per_second = simulation_of(node).setup().pic_ratio_reference_step > 0.0f;
  changed |= ImGui::SliderFloat(per_second ? "PIC ratio (per reference step)" : "PIC ratio", &p.pic_ratio,
                                range.min_pic_ratio, range.max_pic_ratio, "%.3f", clamp);
  changed |= ImGui::SliderFloat("stiffness k", &p.stiffness, range.min_stiffness, range.max_stiffness, "%.1f",
                                ImGuiSliderFlags_Logarithmic | clamp);
  if (changed) node.set_runtime_parameters(p);
}

const ImVec4 k_error_colour(1.0f, 0.4f, 0.3f, 1.0f);

// An error in colour, wrapped to the panel's width; its laid-out size goes into `rect`.
void error_text(const std::string& text, PanelRect& rect) {
  ImGui::PushStyleColor(ImGuiCol_Text, k_error_colour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
  rect.message_width = ImGui::GetItemRectSize().x;
  rect.message_height = ImGui::GetItemRectSize().y;
}

// Keeps a row of widgets inside a narrow panel: the next one goes on this line only if it fits
// (a button: its label and padding; `extra`: what else it has, a check box's box).
void same_line_if_fits(const char* next_label, float extra = 0.0f) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float right = ImGui::GetItemRectMax().x + style.ItemSpacing.x + ImGui::CalcTextSize(next_label).x +
                      2.0f * style.FramePadding.x + extra;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

}  // namespace

PanelRequest draw_panel(Settings& s, MouseTools& mouse, liquid::LiquidNode& node, const Stats& stats,
                        const std::vector<std::filesystem::path>& scenes, const std::filesystem::path& current) {
  PanelRequest request;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float margin = 8.0f;
  const float width = std::min(k_panel_max_width_fraction * display.x, 26.0f * ImGui::GetFontSize());
  // First shown top right (the scenes' liquid starts on the left); after that where it was dragged.
  ImGui::SetNextWindowPos(ImVec2(display.x - margin, margin), ImGuiCond_FirstUseEver, ImVec2(1, 0));
  // The width is fixed (the text wraps to it); the height follows the content up to the window's.
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(display.y - 2.0f * margin, 1.0f)));
  ImGui::SetNextWindowBgAlpha(0.8f);
  const bool open = ImGui::Begin("liquid_viewer", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  // Back inside the window when the window shrank or the panel was dragged past an edge.
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  const ImVec2 inside(std::clamp(pos.x, 0.0f, std::max(display.x - size.x, 0.0f)),
                      std::clamp(pos.y, 0.0f, std::max(display.y - size.y, 0.0f)));
  if (inside.x != pos.x || inside.y != pos.y) ImGui::SetWindowPos(inside);
  request.rect = {inside.x, inside.y, size.x, size.y, ImGui::IsWindowCollapsed()};
  if (!open) {  // collapsed: the title bar only
    ImGui::End();
    return request;
  }
  // Half the width for a slider, half for its label (ImGui's default leaves a narrow panel's
  // labels clipped).
  ImGui::PushItemWidth(0.5f * ImGui::GetContentRegionAvail().x);
  ImGui::TextWrapped("%.1f fps (%.1f ms), %ux%u, %s", stats.fps, stats.frame_ms, stats.width, stats.height,
                     stats.present_mode.c_str());
  ImGui::TextWrapped("t = %.3f s, step %d, %d steps this frame", node.time(), node.step_count(),
                     stats.steps_this_frame);
  if (s.paused) ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.2f, 1.0f), "PAUSED");
  if (s.pacing == Pacing::WallTime) ImGui::TextWrapped("lag behind wall time: %.3f s", stats.lag);
  if (!stats.scene_error.empty()) error_text("reload failed: " + stats.scene_error, request.rect);
  if (!stats.simulation_error.empty()) error_text(stats.simulation_error, request.rect);
  if (!stats.status.empty()) ImGui::TextWrapped("%s", stats.status.c_str());

  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::string name = current.filename().string();
    if (ImGui::BeginCombo("scene", name.c_str())) {
      for (const auto& path : scenes)
        if (ImGui::Selectable(path.filename().string().c_str(), path == current)) request.open_scene = path;
      ImGui::EndCombo();
    }
    if (ImGui::Button(s.paused ? "resume" : "pause")) s.paused = !s.paused;
    same_line_if_fits("step");
    if (ImGui::Button("step")) s.paused = s.step_once = true;
    same_line_if_fits("reset");
    if (ImGui::Button("reset")) request.action = Action::Reset;
    same_line_if_fits("reload");
    if (ImGui::Button("reload")) request.action = Action::Reload;
    same_line_if_fits("shot");
    if (ImGui::Button("shot")) request.action = Action::Screenshot;
    ImGui::Checkbox("FXAA", &s.fxaa);
    if (node.dimension() == 2) {
      same_line_if_fits("particles", ImGui::GetFrameHeight());
      ImGui::Checkbox("particles", &s.particles);
    }
    if (node.scene().whitewater) {
      same_line_if_fits("whitewater", ImGui::GetFrameHeight());
      ImGui::Checkbox("whitewater", &s.whitewater);
    }
  }
  if (ImGui::CollapsingHeader("Pacing and parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    int pacing = int(s.pacing);
    ImGui::RadioButton("steps per frame", &pacing, int(Pacing::FixedSteps));
    same_line_if_fits("wall time", ImGui::GetFrameHeight());
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
    ImGui::TextWrapped("particles %d (outside %d, in obstacles %d)", d.active_particles, d.outside_domain,
                       d.inside_obstacles);
    ImGui::TextWrapped("max rho/rho0 %.3f, max speed %.2f m/s", d.max_density_ratio, d.max_speed);
    ImGui::TextWrapped("kinetic %.4g J, mechanical %.4g J", d.kinetic_energy, d.mechanical_energy);
    for (const liquid::BodyState& b : d.bodies) {  // dynamic obstacles (2D: per metre of depth)
      const glm::vec3 &x = b.pose.center, &v = b.pose.velocity, &w = b.pose.angular_velocity;
      const float angle = glm::degrees(glm::angle(b.pose.orientation));
      ImGui::TextWrapped("body %d (%.3g kg): at (%.3f, %.3f, %.3f) m turned %.1f deg", b.obstacle, b.mass, x.x, x.y, x.z,
                         angle);
      ImGui::TextWrapped("  v (%.3f, %.3f, %.3f) m/s, w (%.2f, %.2f, %.2f) rad/s", v.x, v.y, v.z, w.x, w.y, w.z);
      ImGui::TextWrapped("  liquid's force (%.3g, %.3g, %.3g) N, torque (%.3g, %.3g, %.3g) N m", b.force.x, b.force.y,
                         b.force.z, b.torque.x, b.torque.y, b.torque.z);
    }
  }
  if (ImGui::CollapsingHeader("GPU time per pass (ms)", ImGuiTreeNodeFlags_DefaultOpen) &&
      ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingStretchProp)) {
    // Names take what the milliseconds leave (clipped on a narrow panel).
    ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000.000").x);
    double total = 0.0;
    const auto row = [](const char* name, double ms) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      ImGui::TableNextColumn();
      ImGui::Text("%9.3f", ms);
    };
    for (const auto& p : stats.passes) {
      row(p.name.c_str(), p.milliseconds);
      total += p.milliseconds;
    }
    row("total", total);
    ImGui::EndTable();
  }
  if (ImGui::CollapsingHeader("Keys", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(key_help());
    ImGui::PopTextWrapPos();
  }
  ImGui::PopItemWidth();
  ImGui::End();
  return request;
}

std::vector<std::string> draw_overlay(const Settings& s, const liquid::LiquidNode& node, const Stats& stats,
                                      const std::filesystem::path& current) {
  std::vector<std::string> lines;
  lines.push_back(current.filename().string());
  char line[96];
  std::snprintf(line, sizeof line, "%.1f fps, t = %.3f s", stats.fps, node.time());
  lines.push_back(line);
  if (s.paused) lines.push_back("PAUSED");
  if (!stats.scene_error.empty()) lines.push_back("reload failed (H shows why)");
  if (!stats.simulation_error.empty()) lines.push_back("unstable (H shows why)");
  lines.push_back("H: panel and keys");

  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                      ImVec2(k_panel_max_width_fraction * display.x, std::max(display.y - 16.0f, 1.0f)));
  ImGui::SetNextWindowBgAlpha(0.5f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##overlay", nullptr, flags)) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + k_panel_max_width_fraction * display.x - 16.0f);
    for (const std::string& text : lines) {
      if (text == "PAUSED") ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.2f, 1.0f), "%s", text.c_str());
      else ImGui::TextUnformatted(text.c_str());
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  return lines;
}

}  // namespace viewer
