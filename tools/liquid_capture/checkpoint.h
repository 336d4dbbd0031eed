// checkpoint.bin: the node's whole state after a frame, the stats table up to that frame and a
// fingerprint of the run's settings, written atomically (temporary file renamed into place) so an
// interrupted save leaves the previous checkpoint whole. Binary, so floats come back bit for bit.
#pragma once

#include "liquid/node.h"

#include <cstdint>
#include <filesystem>
#include <string>

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

// FNV-1a, 64 bits: a fingerprint, not a security measure.
uint64_t fingerprint(const std::string& text);

}  // namespace capture
