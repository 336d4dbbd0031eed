// Replayed input (--script FILE): a JSON list of events, each at a frame number, so a run with a
// script is the same run every time:
//   [{"frame": 10, "type": "move", "x": 120, "y": 300},
//    {"frame": 10, "type": "press", "button": "left"},
//    {"frame": 40, "type": "release", "button": "left"},
//    {"frame": 50, "type": "key", "key": "f"},
//    {"frame": 60, "type": "scroll", "delta": 1, "ctrl": true},
//    {"frame": 70, "type": "resize", "width": 320, "height": 200}]
// A press or release happens at the cursor of the last move.
// From the first mouse event on, the panel sees the script's mouse instead of the window's, as it
// stands when each frame's events are done (a press and its release in one frame are no click to it).
#pragma once

#include "tools/liquid_viewer/input.h"

#include <filesystem>
#include <vector>

namespace viewer {

struct ScriptEvent {
  int frame = 0;
  InputEvent event;
};

class Script {
 public:
  Script() = default;
  // Throws std::runtime_error naming the file and the event that is wrong.
  explicit Script(const std::filesystem::path& path);
  // The events of frame `frame`, in file order.
  std::vector<InputEvent> events_at(int frame) const;
  int last_frame() const { return events_.empty() ? -1 : events_.back().frame; }
  bool empty() const { return events_.empty(); }

 private:
  std::vector<ScriptEvent> events_;  // sorted by frame, stable
};

}  // namespace viewer
