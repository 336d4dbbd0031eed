// --video: frames piped as raw RGBA into Debian's ffmpeg as they are written (H.264, yuv420p),
// into "<name>.partial" renamed into place when the run ends, so a cut-off encode never looks
// complete. ffmpeg runs in its own process group: a Ctrl-C reaches only the capture tool, which
// then closes the pipe and lets ffmpeg finish the file for the frames written.
#pragma once

#include "engine/io/png.h"

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>

namespace capture {

// The program's path when an executable of that name is on PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& program);

class VideoEncoder {
 public:
  // Starts ffmpeg; throws std::runtime_error with one line when it is not installed or cannot start.
  VideoEncoder(std::filesystem::path path, uint32_t width, uint32_t height, double fps);
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;
  // Stops an unfinished encode and removes its partial file.
  ~VideoEncoder();

  void add(const engine::vk::Rgba8Image& frame);
  // Closes the pipe, waits for ffmpeg and renames the file into place; throws with ffmpeg's last
  // message when it failed.
  void finish();

 private:
  std::string ffmpeg_message() const;
  std::filesystem::path path_, partial_, log_;
  uint32_t width_, height_;
  pid_t pid_ = -1;
  int pipe_ = -1;
};

}  // namespace capture
