// Golden-image comparison: a per-channel threshold and the fraction of pixels allowed over it.
// On failure the actual image and a diff image are written under the build folder and their
// paths are in the message. Goldens are rewritten only when LIQUID_UPDATE_GOLDENS=1.
#pragma once

#include "engine/io/png.h"

#include <string>

namespace test {

struct CompareTolerance {
  int channel_threshold = 8;         // a pixel differs when any channel differs by more (0..255)
  double max_differing_fraction = 0.002;  // fraction of pixels allowed to differ
};

struct CompareResult {
  bool passed = false;
  double differing_fraction = 0.0;
  int max_channel_difference = 0;
  std::string message;  // what happened, with the paths of the actual and diff images
};

// Compares `actual` with tests/goldens/<name>.png.
CompareResult compare_with_golden(const engine::vk::Rgba8Image& actual, const std::string& name,
                                  const CompareTolerance& tolerance);

// The same comparison of two images in memory (no files).
CompareResult compare_images(const engine::vk::Rgba8Image& actual, const engine::vk::Rgba8Image& expected,
                             const CompareTolerance& tolerance);

}  // namespace test
