// The viewer's keyboard controls and the settings the keys and the panel change, and the two
// pacing modes: the chapter's fixed steps per frame, or simulated time following wall time.
#pragma once

#include <string>

namespace viewer {

enum class Pacing { FixedSteps, WallTime };

struct Settings {
  bool paused = false;
  bool step_once = false;  // one step while paused
  bool fxaa = true;
  bool particles = false;  // 2D: particles drawn over the liquid
  bool whitewater = true;  // 3D scenes with whitewater: spray, foam and bubbles drawn
  bool panel = true;
  bool overlay = true;     // the small overlay while the panel is hidden
  Pacing pacing = Pacing::FixedSteps;
  int steps_per_frame = 1;  // FixedSteps (the chapter: one step per frame)
  int max_steps_per_frame = 16;  // WallTime's cap, and the node's uniform space
};

// What a key asks the viewer to do beyond changing `Settings`.
enum class Action { None, Reset, Reload, Screenshot, NextScene, PreviousScene, Quit };

// Applies key `key` (a GLFW key code) to the settings; returns the action it asks for.
Action apply_key(int key, Settings& settings);

// The key table, for the panel and the README: "Space  pause / resume", ...
const char* key_help();

// GLFW key code of a name in a script ("space", "r", "f5", "escape"); -1 when unknown.
int key_code(const std::string& name);

// WallTime pacing: steps this frame for `wall_seconds` since the last frame, carrying the
// remainder; the lag is the simulated time behind wall time that the cap left (at most 1 s).
class WallClock {
 public:
  int steps(double wall_seconds, double time_step, int cap);
  double lag() const { return lag_; }
  void reset() { lag_ = 0.0; }

 private:
  double lag_ = 0.0;
};

}  // namespace viewer
