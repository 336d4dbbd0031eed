// The viewer's state and its frame (app.h runs it): construction and input in viewer.cpp, the
// recorded frame in frame_recording.cpp, the exit report in report.cpp.
#pragma once

#include "engine/vk/context.h"
#include "tools/liquid_viewer/app.h"
#include "tools/liquid_viewer/controls.h"
#include "tools/liquid_viewer/frame_in_flight.h"
#include "tools/liquid_viewer/imgui_layer.h"
#include "tools/liquid_viewer/input.h"
#include "tools/liquid_viewer/panel.h"
#include "tools/liquid_viewer/present_pass.h"
#include "tools/liquid_viewer/script.h"
#include "tools/liquid_viewer/session.h"
#include "tools/liquid_viewer/swapchain.h"
#include "tools/liquid_viewer/window.h"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace viewer {

constexpr uint32_t k_frames_in_flight = 2;

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options);
  ~Viewer();
  // Runs until the window closes or --frames is reached; returns the exit code.
  int run();

 private:
  // viewer.cpp
  void handle(const InputEvent& event, bool from_window);
  void follow_script_pointer(const InputEvent& event);
  // ImGui's frame: the panel, or the overlay while it is hidden; false when neither is drawn.
  bool draw_ui();
  void perform(Action action);
  void open(const std::filesystem::path& scene);
  void wait_all();
  bool ensure_swapchain();
  void refresh_diagnostics();
  // The next free viewer_NNNN.png of the working folder, created (empty) so that no one else takes it;
  // empty (with the reason in the panel's status) when it cannot be created.
  std::filesystem::path next_screenshot_path();
  // frame_recording.cpp
  int steps_for_frame(double wall_seconds);
  void apply_mouse(int steps);
  // Records and submits one frame into swapchain image `index`; false when the swapchain must be
  // recreated first.
  bool draw_frame(FrameSlot& slot, int steps, double wall_seconds);
  void read_timings(FrameSlot& slot);
  // report.cpp
  void write_report(const std::filesystem::path& path);

  ViewerOptions options_;
  Window window_;
  std::unique_ptr<engine::vk::Context> context_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  std::unique_ptr<Swapchain> swapchain_;
  std::unique_ptr<Session> session_;
  std::unique_ptr<ImGuiLayer> imgui_;
  std::unique_ptr<PresentPass> present_;
  std::array<std::unique_ptr<FrameSlot>, k_frames_in_flight> slots_;
  Script script_;
  Settings settings_;
  MouseTools mouse_;
  WallClock clock_;
  Stats stats_;
  std::vector<std::filesystem::path> scenes_;
  bool recreate_ = true;
  bool shot_requested_ = false;
  int frame_ = 0;           // frames presented or skipped (minimized), the script's clock
  int drawn_frames_ = 0;    // frames presented
  double fps_time_ = 0.0;
  double first_frame_time_ = -1.0;  // glfwGetTime() when the first frame was submitted
  double last_frame_time_ = 0.0;
  int fps_frames_ = 0;
  std::optional<glm::vec3> last_brush_;  // for the report
  // A script's mouse, which the panel sees in a replayed run (from the script's first mouse event).
  std::optional<ScriptedPointer> script_pointer_;
  bool imgui_frame_ = false;  // this frame draws ImGui (the panel or the overlay)
  std::optional<PanelRect> panel_rect_;     // where the panel was last drawn (for the report)
  std::vector<std::string> overlay_lines_;  // what the overlay showed this frame (for the report)
};

}  // namespace viewer
