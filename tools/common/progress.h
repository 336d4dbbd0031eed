// Progress display for long command-line runs: a one-line bar redrawn in place on a terminal,
// plain lines otherwise (CI logs, pipes), so logs stay readable.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace tools {

class Progress {
 public:
  explicit Progress(int total) : total_(total), terminal_(isatty(fileno(stdout)) == 1) {}

  // Reports that `done` of the total items are finished, with a rate (`unit` per second) and the
  // time left estimated from the average so far.
  void update(int done, double rate, const char* unit) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = done > 0 ? elapsed / done * (total_ - done) : 0.0;
    const std::string eta = format_duration(left);
    if (terminal_) {
      constexpr int k_width = 30;
      const int filled = total_ > 0 ? done * k_width / total_ : k_width;
      std::printf("\r[%s%s] frame %d of %d  %.1f %s/s  %s left ", std::string(size_t(filled), '#').c_str(),
                  std::string(size_t(k_width - filled), ' ').c_str(), done, total_, rate, unit, eta.c_str());
      if (done == total_) std::printf("\n");
    } else {
      std::printf("frame %d of %d: %.1f %s/s, %s left\n", done, total_, rate, unit, eta.c_str());
    }
    std::fflush(stdout);
  }

  // Ends a bar left unfinished (an error mid-run), so the error starts on its own line.
  void interrupt() const {
    if (terminal_) std::printf("\n");
  }

 private:
  static std::string format_duration(double seconds) {
    const int s = int(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%d:%02d", s / 60, s % 60);
    return text;
  }

  int total_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// A set-up stage that may take a while (reading large meshes, carving the particles around them,
// compiling pipelines): on a terminal, "tool: what..." while it runs, replaced by what comes next,
// so a long wait never looks like a hang; elsewhere (logs, pipes) nothing.
class SetupStage {
 public:
  SetupStage(const char* tool, const char* what) : terminal_(isatty(fileno(stdout)) == 1) {
    if (!terminal_) return;
    std::printf("\r\033[K%s: %s...", tool, what);
    std::fflush(stdout);
  }
  ~SetupStage() {
    if (!terminal_) return;
    std::printf("\r\033[K");  // the stage's line cleared, for the next line or an error
    std::fflush(stdout);
  }
  SetupStage(const SetupStage&) = delete;
  SetupStage& operator=(const SetupStage&) = delete;

 private:
  bool terminal_;
};

}  // namespace tools
