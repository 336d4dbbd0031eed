// The viewer group: liquid_viewer's frame rate on the dam breaks, as a person sees it, measured by
// running the viewer for a fixed number of frames on an X display of the benchmark's own (Xvfb).
#pragma once

#include "tools/liquid_benchmark/plan.h"
#include "tools/liquid_benchmark/process.h"
#include "tools/liquid_benchmark/run.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace tools::benchmark {

// The display the viewer runs on, opened once for the group: an Xvfb of its own when Xvfb is
// installed (as the viewer's tests run it), else $DISPLAY when set, else none.
class ViewerDisplay {
 public:
  ViewerDisplay(uint32_t width, uint32_t height);

  const std::optional<std::string>& display() const { return display_; }
  const std::string& what() const { return what_; }  // "Xvfb :3", "$DISPLAY :0", or why there is none

 private:
  std::unique_ptr<Xvfb> xvfb_;
  std::optional<std::string> display_;
  std::string what_;
};

// liquid_viewer beside this program's own binary (the build's bin folder); throws naming the path
// when there is none.
std::filesystem::path viewer_beside_benchmark();

// Runs `o.viewer` on the configuration's scene for its timed frames at the options' frame size
// on the display (which must have one; with --validation when the benchmark has it) and reads its
// --report: the frame rate over the
// frames after the first becomes the result's frame time. Its report and output go to `work`.
// Throws with the viewer's error line when it fails.
Result run_viewer(const Configuration& c, const Options& o, const ViewerDisplay& display,
                  const std::filesystem::path& work);

}  // namespace tools::benchmark
