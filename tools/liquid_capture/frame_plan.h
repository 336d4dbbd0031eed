// Which frames a capture simulates and writes, and what each file is called. Frame f is the state
// after f * steps_per_frame solver steps (frame 0 is the initial state, t = 0); frames before
// `start` are simulated but not written, as in Blender's frame range.
#pragma once

#include <string>

namespace capture {

// The name with its frame number field in the '#' form: printf's %04d (or %d) and Houdini's $F4
// (or $F) become a run of that many '#', so "liquid_%04d.png" and "liquid_$F4.png" are
// "liquid_####.png". Other text is kept as it is.
std::string hash_form(const std::string& name);
// Whether the name has a frame number field in any of those forms.
bool has_frame_field(const std::string& name);

// A file name with one run of '#' for the frame number, zero-padded to that many digits (wider
// numbers keep all their digits): "liquid_####.png" -> liquid_0007.png. Given as %04d or $F4, it
// is kept in the '#' form (capture.json records that).
class NamePattern {
 public:
  NamePattern() = default;
  // Throws std::invalid_argument naming `flag` when the text is not a plain file name with exactly
  // one run of '#' (or %04d, $F4) ending in `extension` (".png").
  static NamePattern parse(const std::string& text, const std::string& flag, const std::string& extension);

  std::string name(int frame) const;
  // Whether a file name is one this pattern produces (its .partial temporary included when asked).
  bool matches(const std::string& file_name, bool or_partial = false) const;
  const std::string& text() const { return text_; }

 private:
  std::string text_, prefix_, suffix_;
  int width_ = 1;
};

struct FramePlan {
  int start = 1;            // first frame written
  int end = 60;             // last frame written (inclusive)
  int steps_per_frame = 8;
  double time_step = 0.0;   // s: the scene's, or with --fps the step that fits a whole number in a frame
  double fps = 0.0;         // the --fps asked for, exactly (0: the rate follows from the steps)

  int written() const { return end - start + 1; }
  double frame_seconds() const { return fps > 0.0 ? 1.0 / fps : steps_per_frame * time_step; }
  double frames_per_second() const { return fps > 0.0 ? fps : 1.0 / frame_seconds(); }
};

// Steps per frame from the flags: --steps-per-frame wins, then --fps (0: not given), then the
// scene's substeps. With --fps, the fewest steps of at most `time_step` that fill 1 / fps, so the
// step is then shortened to 1 / (fps * steps) and every frame lasts exactly 1 / fps. Throws
// std::invalid_argument when --fps needs more than `max_steps` steps.
int steps_per_frame(int steps_flag, double fps, double time_step, int substeps, int max_steps);

}  // namespace capture
