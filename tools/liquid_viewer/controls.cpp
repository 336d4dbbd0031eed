#include "tools/liquid_viewer/controls.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace viewer {

Action apply_key(int key, Settings& s) {
  switch (key) {
    case GLFW_KEY_SPACE: s.paused = !s.paused; return Action::None;
    case GLFW_KEY_N: s.paused = true; s.step_once = true; return Action::None;
    case GLFW_KEY_R: return Action::Reset;
    case GLFW_KEY_F: s.fxaa = !s.fxaa; return Action::None;
    case GLFW_KEY_P: s.particles = !s.particles; return Action::None;
    case GLFW_KEY_W: s.whitewater = !s.whitewater; return Action::None;
    case GLFW_KEY_H: s.panel = !s.panel; return Action::None;
    case GLFW_KEY_O: s.overlay = !s.overlay; return Action::None;
    case GLFW_KEY_T:
      s.pacing = s.pacing == Pacing::FixedSteps ? Pacing::WallTime : Pacing::FixedSteps;
      return Action::None;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: s.steps_per_frame = std::min(s.steps_per_frame + 1, s.max_steps_per_frame); return Action::None;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: s.steps_per_frame = std::max(s.steps_per_frame - 1, 1); return Action::None;
    case GLFW_KEY_F12:
    case GLFW_KEY_S: return Action::Screenshot;
    case GLFW_KEY_F5:
    case GLFW_KEY_L: return Action::Reload;
    case GLFW_KEY_PAGE_DOWN: return Action::NextScene;
    case GLFW_KEY_PAGE_UP: return Action::PreviousScene;
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: return Action::Quit;
    default: return Action::None;
  }
}

const char* key_help() {
  return "Space      pause / resume\n"
         "N          one step (pauses)\n"
         "R          reset the scene and the camera\n"
         "L, F5      reload the scene file (also automatic when it changes)\n"
         "PgDn, PgUp next / previous scene of assets/scenes\n"
         "F          FXAA on / off\n"
         "P          particles over the liquid (2D)\n"
         "W          spray, foam and bubbles drawn (3D scenes with whitewater)\n"
         "T          pacing: fixed steps per frame / wall time\n"
         "+, -       steps per frame\n"
         "S, F12     screenshot (viewer_NNNN.png)\n"
         "H          hide / show this panel (hidden: an overlay)\n"
         "O          the overlay on / off\n"
         "Esc, Q     quit\n"
         "Left drag  force brush (wheel: radius)\n"
         "Right drag move the nearest obstacle\n"
         "Middle drag orbit (3D, shallow water), Shift + middle drag pan, Ctrl + wheel zoom\n"
         "Title bar  drag to move this panel, its arrow folds it";
}

int key_code(const std::string& name) {
  static const std::map<std::string, int> named = {
      {"space", GLFW_KEY_SPACE}, {"escape", GLFW_KEY_ESCAPE}, {"f5", GLFW_KEY_F5},   {"f12", GLFW_KEY_F12},
      {"plus", GLFW_KEY_EQUAL},  {"minus", GLFW_KEY_MINUS},   {"pagedown", GLFW_KEY_PAGE_DOWN},
      {"pageup", GLFW_KEY_PAGE_UP}};
  if (const auto it = named.find(name); it != named.end()) return it->second;
  if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
    return GLFW_KEY_A + (std::tolower(static_cast<unsigned char>(name[0])) - 'a');
  return -1;
}

int WallClock::steps(double wall_seconds, double time_step, int cap) {
  lag_ += std::clamp(wall_seconds, 0.0, 0.25);  // a stall (a window drag, a reload) is not caught up
  const int n = std::min(int(std::floor(lag_ / time_step)), cap);
  lag_ -= n * time_step;
  lag_ = std::min(lag_, 1.0);  // past a second behind, the viewer stops trying to catch up
  return std::max(n, 0);
}

}  // namespace viewer
