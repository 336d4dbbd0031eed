#include "tools/liquid_viewer/viewer.h"

#include "engine/vk/vk_check.h"
#include "liquid/analysis/diagnostics.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace viewer {

// How often the viewer reads the state back to check it and size the next steps (a readback waits
// for the frames in flight, so not every frame).
constexpr int k_diagnose_every_frames = 30;
namespace {

engine::vk::ContextOptions context_options(bool validation) {
  engine::vk::ContextOptions o;
  o.validation = validation;
  o.instance_extensions = Window::instance_extensions();
  o.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  o.queue_family_filter = Window::can_present;
  return o;
}

std::vector<std::filesystem::path> list_scenes(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> scenes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options), window_("liquid_viewer", options.width, options.height) {
  context_ = std::make_unique<engine::vk::Context>(context_options(options.validation));
  surface_ = window_.create_surface(context_->instance());
  swapchain_ = std::make_unique<Swapchain>(*context_, surface_, options.unthrottled);
  settings_.panel = options.panel;
  settings_.overlay = options.overlay;
  settings_.pacing = options.pacing;
  settings_.steps_per_frame = std::clamp(options.steps_per_frame, 1, settings_.max_steps_per_frame);
  session_ = std::make_unique<Session>(*context_, options.scene, k_frames_in_flight, settings_.max_steps_per_frame,
                                       options.grid_path);
  scenes_ = list_scenes(options.scenes_dir);
  if (!options.script.empty()) script_ = Script(options.script);
  uint32_t w = 0, h = 0;
  window_.framebuffer_size(w, h);
  if (!swapchain_->recreate(w, h)) throw std::runtime_error("the window has no area");
  recreate_ = false;
  imgui_ = std::make_unique<ImGuiLayer>(*context_, window_.handle(), *swapchain_);
  present_ = std::make_unique<PresentPass>(*context_, swapchain_->format());
  for (auto& slot : slots_) slot = std::make_unique<FrameSlot>(*context_);
  stats_.present_mode = present_mode_name(swapchain_->present_mode());

  mouse_.surface_hit = [this](glm::vec3 origin, glm::vec3 direction) {
    wait_all();  // the density is read back: no frame of the node may be in flight
    return session_->surface_hit(origin, direction);
  };
  mouse_.obstacle_centers = [this] {
    std::vector<glm::vec3> centers;
    for (const auto& pose : session_->node().obstacle_poses(session_->node().time())) centers.push_back(pose.center);
    return centers;
  };
  std::printf("liquid_viewer: %s on %s, %ux%u %s, %s\n", options.scene.string().c_str(), context_->device_name().c_str(),
              swapchain_->extent().width, swapchain_->extent().height, stats_.present_mode.c_str(),
              swapchain_->bgra() ? "BGRA swapchain (the present pass writes RGBA into it)" : "RGBA swapchain");
  std::fflush(stdout);  // the window is up (a test waits for this line)
}

Viewer::~Viewer() {
  if (context_) vkDeviceWaitIdle(context_->device());
  for (auto& slot : slots_) slot.reset();
  imgui_.reset();
  present_.reset();
  session_.reset();
  swapchain_.reset();
  if (surface_) vkDestroySurfaceKHR(context_->instance(), surface_, nullptr);
}

void Viewer::wait_all() {
  for (auto& slot : slots_) slot->wait();
}

void Viewer::handle(const InputEvent& e, bool from_window) {
  if (e.type == InputEvent::Type::Resize) {
    window_.set_size(std::max(e.width, 1u), std::max(e.height, 1u));
    return;
  }
  if (e.type == InputEvent::Type::Key) {
    if (from_window && settings_.panel && imgui_->wants_keyboard()) return;
    perform(apply_key(e.key, settings_));
    return;
  }
  if (!from_window) follow_script_pointer(e);
  // The panel takes the mouse over its window (the window's, or a script's once it moves the
  // mouse); a release always reaches the tools (no stuck drag).
  const bool panel_sees_it = from_window || script_pointer_;
  const bool over_panel = panel_sees_it && settings_.panel && imgui_->wants_mouse();
  if (over_panel && e.type != InputEvent::Type::Release && e.type != InputEvent::Type::Move) return;
  mouse_.handle(e, session_->mapping(), session_->camera());
}

void Viewer::follow_script_pointer(const InputEvent& e) {
  if (e.type != InputEvent::Type::Move && e.type != InputEvent::Type::Press && e.type != InputEvent::Type::Release &&
      e.type != InputEvent::Type::Scroll)
    return;
  ScriptedPointer& p = script_pointer_ ? *script_pointer_ : script_pointer_.emplace();
  p.x = e.x;
  p.y = e.y;
  if (e.type == InputEvent::Type::Scroll) p.wheel += e.scroll;
  if (e.type == InputEvent::Type::Press || e.type == InputEvent::Type::Release)
    p.down[e.button == MouseButton::Left ? 0 : e.button == MouseButton::Right ? 1 : 2] =
        e.type == InputEvent::Type::Press;
}

bool Viewer::draw_ui() {
  overlay_lines_.clear();
  if (!settings_.panel && !settings_.overlay) return false;
  imgui_->new_frame(script_pointer_ ? &*script_pointer_ : nullptr);
  if (script_pointer_) script_pointer_->wheel = 0.0f;
  if (!settings_.panel) {
    overlay_lines_ = draw_overlay(settings_, session_->node(), stats_, session_->path());
    return true;
  }
  const PanelRequest request = draw_panel(settings_, mouse_, session_->node(), stats_, scenes_, session_->path());
  panel_rect_ = request.rect;
  if (request.open_scene) open(*request.open_scene);
  perform(request.action);
  return true;
}

std::filesystem::path Viewer::next_screenshot_path() {
  // After the highest viewer_NNNN.png already in the working folder (earlier sessions' included),
  // so a new shot never replaces an old one and the numbers follow the order they were taken in.
  int next = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(".", error)) {
    int n = 0;
    char end = 0;
    if (std::sscanf(entry.path().filename().c_str(), "viewer_%d.pn%c", &n, &end) == 2 && end == 'g' && n >= next)
      next = n + 1;
  }
  // The name is taken by creating the file exclusively (O_EXCL), so another viewer saving into the
  // same folder at the same time cannot take it too; the PNG replaces this empty file once the
  // frame is read back.
  for (;; ++next) {
    char name[32];
    std::snprintf(name, sizeof name, "viewer_%04d.png", next);
    const int fd = ::open(name, O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      ::close(fd);
      return name;
    }
    if (errno != EEXIST) {
      stats_.status = std::string("screenshot failed: ") + name + ": " + std::strerror(errno);
      return {};
    }
  }
}

void Viewer::perform(Action action) {
  switch (action) {
    case Action::None: return;
    case Action::Quit: window_.request_close(); return;
    case Action::Screenshot: shot_requested_ = true; return;
    case Action::Reset:
      wait_all();
      session_->reset();
      clock_.reset();
      stats_.simulation_error.clear();
      stats_.diagnostics.reset();
      return;
    case Action::Reload: {
      wait_all();
      const std::optional<std::string> error = session_->reload();
      stats_.scene_error = error.value_or("");
      stats_.simulation_error.clear();
      if (error) std::fprintf(stderr, "liquid_viewer: reload failed, the old scene keeps running: %s\n", error->c_str());
      window_.set_title(error ? "liquid_viewer: reload failed: " + *error : "liquid_viewer");
      return;
    }
    case Action::NextScene:
    case Action::PreviousScene: {
      if (scenes_.empty()) return;
      const auto it = std::find(scenes_.begin(), scenes_.end(), session_->path());
      const long n = long(scenes_.size());
      long i = it == scenes_.end() ? 0 : long(it - scenes_.begin()) + (action == Action::NextScene ? 1 : -1);
      open(scenes_[size_t(((i % n) + n) % n)]);
      return;
    }
  }
}

void Viewer::open(const std::filesystem::path& scene) {
  wait_all();
  try {
    auto next = std::make_unique<Session>(*context_, scene, k_frames_in_flight, settings_.max_steps_per_frame,
                                          options_.grid_path);
    session_.reset();
    session_ = std::move(next);
    stats_.scene_error.clear();
    stats_.simulation_error.clear();
    stats_.diagnostics.reset();
    clock_.reset();
  } catch (const std::exception& error) {
    stats_.scene_error = error.what();
    std::fprintf(stderr, "liquid_viewer: cannot open %s: %s\n", scene.string().c_str(), error.what());
  }
}

bool Viewer::ensure_swapchain() {
  uint32_t w = 0, h = 0;
  window_.framebuffer_size(w, h);
  if (w == 0 || h == 0 || glfwGetWindowAttrib(window_.handle(), GLFW_ICONIFIED)) return false;  // minimized
  const VkExtent2D e = swapchain_->extent();
  if (!recreate_ && e.width == w && e.height == h) return true;
  wait_all();
  VK_CHECK(vkDeviceWaitIdle(context_->device()));  // the presentation engine is done with the old images
  if (!swapchain_->recreate(w, h)) return false;
  imgui_->on_swapchain_recreated(*swapchain_);
  recreate_ = false;
  return true;
}

void Viewer::refresh_diagnostics() {
  wait_all();
  try {
    stats_.diagnostics = session_->node().diagnose();
    session_->node().adapt_time_step(*stats_.diagnostics);  // the scene's adaptive_time_step, if any
  } catch (const liquid::SimulationError& error) {
    stats_.simulation_error = std::string("unstable, paused: ") + error.what();
    settings_.paused = true;
  }
}

int Viewer::run() {
  double last = glfwGetTime();
  fps_time_ = last;
  while (!window_.should_close()) {
    glfwPollEvents();
    for (const InputEvent& e : script_.events_at(frame_)) handle(e, false);
    for (const InputEvent& e : window_.take_events()) handle(e, true);
    if (session_->file_changed()) perform(Action::Reload);
    const double now = glfwGetTime();
    const double wall = now - last;
    last = now;
    if (!ensure_swapchain()) {  // minimized: nothing to draw, the simulation waits
      if (script_.empty() && options_.frames == 0) glfwWaitEventsTimeout(0.1);
      if (++frame_ >= options_.frames && options_.frames > 0) break;
      continue;
    }
    const VkExtent2D extent = swapchain_->extent();
    if (session_->needs_view(extent.width, extent.height, settings_)) {
      wait_all();
      session_->set_view(extent.width, extent.height, settings_);
    }
    imgui_frame_ = draw_ui();
    FrameSlot& slot = *slots_[size_t(drawn_frames_) % k_frames_in_flight];
    slot.wait();
    read_timings(slot);
    if (!draw_frame(slot, steps_for_frame(wall), wall)) {
      recreate_ = true;
      continue;
    }
    ++drawn_frames_;
    ++fps_frames_;
    if (first_frame_time_ < 0.0) first_frame_time_ = now;
    last_frame_time_ = now;
    if (now - fps_time_ >= 0.5) {
      stats_.fps = fps_frames_ / (now - fps_time_);
      stats_.frame_ms = 1000.0 * (now - fps_time_) / fps_frames_;
      fps_time_ = now;
      fps_frames_ = 0;
    }
    // On the simulation's own schedule, whatever the window shows: the stability check (which
    // pauses an exploded run) and the adaptive step must not depend on whether the panel is open.
    if (drawn_frames_ % k_diagnose_every_frames == 1) refresh_diagnostics();
    if (++frame_ >= options_.frames && options_.frames > 0) break;
  }
  wait_all();
  VK_CHECK(vkDeviceWaitIdle(context_->device()));
  if (!options_.report.empty()) write_report(options_.report);
  const uint32_t messages = context_->validation_message_count();
  std::printf("liquid_viewer: %d frames drawn, %d steps, %u swapchain recreation(s), %u validation message(s)\n",
              drawn_frames_, session_->node().step_count(), swapchain_->recreations(), messages);
  if (messages > 0) throw std::runtime_error(std::to_string(messages) + " validation message(s)");
  return 0;
}

int run_viewer(const ViewerOptions& options) {
  Viewer viewer(options);
  return viewer.run();
}

}  // namespace viewer
