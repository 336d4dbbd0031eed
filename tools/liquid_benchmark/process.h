// Other programs the benchmark runs: another build's benchmark (alternating comparison), the
// viewer, and the Xvfb server it draws into. posix_spawn, not fork: the benchmark may hold a
// Vulkan device whose driver runs threads.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace tools::benchmark {

// Runs argv[0] (a path, or a name looked up in PATH) with `env` (KEY=VALUE) added to this
// process's environment, its stdout and stderr both into `log`; waits and returns the exit code
// (128 + the signal when a signal ended it). Throws when the program cannot be started.
int run_process(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                const std::filesystem::path& log);

// The line of a log that says why a program failed: its last line holding "error", else its last
// non-empty line, else "(no output)".
std::string failure_line(const std::filesystem::path& log);

// This program's own executable (/proc/self/exe).
std::filesystem::path own_binary();

// The program's path when `name` is found in PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

// An X server of its own for the viewer, as tests/viewer/with_xvfb.sh starts one: Xvfb picks a
// free display number (-displayfd); the server is stopped when this is destroyed.
class Xvfb {
 public:
  // Throws std::runtime_error when Xvfb does not start or gives no display number within 10 s.
  Xvfb(const std::filesystem::path& program, int width, int height);
  ~Xvfb();
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;

  const std::string& display() const { return display_; }  // ":N"

 private:
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace tools::benchmark
