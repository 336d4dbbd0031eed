// checkpoint.bin: the node's whole state after a frame, the stats table up to that frame and a
// fingerprint of the run's settings, written atomically (temporary file renamed into place) so an
// interrupted save leaves the previous checkpoint whole. Binary, so floats come back bit for bit.
#pragma once

#include "liquid/node.h"
#include "tools/liquid_capture/frame_plan.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace capture {

struct CaptureCheckpoint {
  int frame = 0;                 // the last frame simulated (and, if in range, written)
  uint64_t settings_hash = 0;    // of the recorded settings: a checkpoint only resumes its own run
  liquid::LiquidNode::Checkpoint node;
  std::string stats_csv;         // stats.csv as it was after `frame`
};

void save_checkpoint(const std::filesystem::path& path, const CaptureCheckpoint& checkpoint);
// Throws std::runtime_error naming the path when the file is missing, truncated or not a checkpoint.
CaptureCheckpoint load_checkpoint(const std::filesystem::path& path);

// A file a resume reads back (checkpoint.bin, capture.json), sized before it is read: it must be a
// regular file of at most `max_bytes`, else "PATH: not a KIND (not a regular file of at most N
// MiB)", so an oversized file or a link to /dev/zero is refused without being read.
std::string read_sized_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& kind);

// FNV-1a, 64 bits: a fingerprint against damage and mix-ups, not a security measure.
uint64_t fingerprint(std::string_view text);

// The largest checkpoint.bin read back: 2^26 particles of five vec4 textures (position, velocity and
// the affine transfer's three of C_p) and two per whitewater slot (at most 8 a particle), the
// pressure projection's grid of up to 2^29 floats (p and psi of a 645^3 grid), and the table.
inline constexpr std::uintmax_t k_max_checkpoint_bytes =
    (std::uintmax_t(1) << 26) * (80 + 8 * 32) + (std::uintmax_t(1) << 29) * 4 + (std::uintmax_t(256) << 20);

// Throws std::runtime_error naming `source` when the checkpoint disagrees with the run recorded in
// capture.json: its frame outside the plan, its clock not at that frame's time, or its table not
// holding one row per frame written up to it.
void check_against_plan(const CaptureCheckpoint& checkpoint, const FramePlan& plan, const std::string& source);

}  // namespace capture
