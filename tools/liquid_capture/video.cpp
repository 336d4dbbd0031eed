#include "tools/liquid_capture/video.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace capture {

namespace fs = std::filesystem;

std::optional<fs::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
  }
  return std::nullopt;
}

namespace {

const char* muxer_for(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".mkv" ? "matroska" : ext == ".mov" ? "mov" : "mp4";
}

}  // namespace

VideoEncoder::VideoEncoder(fs::path path, uint32_t width, uint32_t height, double fps)
    : path_(std::move(path)), width_(width), height_(height) {
  const std::optional<fs::path> ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg)
    throw std::runtime_error("--video needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg)");
  partial_ = path_;
  partial_ += ".partial";
  char log_name[] = "/tmp/liquid_capture_ffmpeg_XXXXXX";
  const int log_fd = ::mkstemp(log_name);
  if (log_fd < 0) throw std::runtime_error("--video: cannot create a log file for ffmpeg in /tmp");
  log_ = log_name;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    ::close(log_fd);
    throw std::runtime_error("--video: cannot create a pipe to ffmpeg");
  }

  char size[32], rate[32];
  std::snprintf(size, sizeof size, "%ux%u", width, height);
  std::snprintf(rate, sizeof rate, "%.17g", fps);
  // yuv420p (what players expect) needs even sides: pad by one pixel where odd.
  std::vector<std::string> args = {ffmpeg->string(), "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                   "-pix_fmt", "rgba", "-s", size, "-framerate", rate, "-i", "pipe:0",
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                                   // "file:" and an absolute path: a name like "-x.mp4" or "rel:b.mp4" cannot
                                   // be read as an option or a protocol.
                                   "-f", muxer_for(path_), "file:" + fs::absolute(partial_).string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_adddup2(&actions, log_fd, 1);
  posix_spawn_file_actions_adddup2(&actions, log_fd, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF);
  const int error = posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(fds[0]);
  ::close(log_fd);
  if (error != 0) {
    ::close(fds[1]);
    pid_ = -1;
    throw std::runtime_error("--video: cannot start " + ffmpeg->string() + " (" + std::strerror(error) + ")");
  }
  pipe_ = fds[1];
}

VideoEncoder::~VideoEncoder() {
  std::error_code ignored;
  if (pipe_ >= 0) ::close(pipe_);
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    fs::remove(partial_, ignored);
  }
  if (!log_.empty()) fs::remove(log_, ignored);
}

std::string VideoEncoder::ffmpeg_message() const {
  std::ifstream log(log_);
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

void VideoEncoder::add(const engine::vk::Rgba8Image& frame) {
  if (frame.width != width_ || frame.height != height_) throw std::logic_error("--video: frame size changed");
  const uint8_t* data = frame.pixels.data();
  size_t left = frame.pixels.size();
  while (left > 0) {
    const ssize_t n = ::write(pipe_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("--video: ffmpeg stopped (" + ffmpeg_message() + ")");
    data += n;
    left -= size_t(n);
  }
}

void VideoEncoder::finish() {
  ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::error_code error;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fs::remove(partial_, error);
    throw std::runtime_error("--video " + path_.string() + ": ffmpeg failed (" + ffmpeg_message() + ")");
  }
  fs::rename(partial_, path_, error);
  if (error) throw std::runtime_error(path_.string() + ": cannot rename into place (" + error.message() + ")");
}

}  // namespace capture
