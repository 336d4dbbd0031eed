// compare_golden ACTUAL.png NAME: compares a PNG written by a program (the host example) with
// tests/goldens/NAME.png under the suite's tolerance rules (LIQUID_UPDATE_GOLDENS=1 rewrites it).
#include "tests/support/image_compare.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: compare_golden ACTUAL.png GOLDEN_NAME\n");
    return 2;
  }
  try {
    // The composited frame: per-channel threshold 8, 0.5% of pixels may differ (CPU vector paths
    // can move a few edge pixels).
    const test::CompareResult result =
        test::compare_with_golden(engine::vk::read_png(argv[1]), argv[2], test::CompareTolerance{8, 0.005});
    std::printf("%s\n", result.message.c_str());
    return result.passed ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "compare_golden: error: %s\n", error.what());
    return 1;
  }
}
