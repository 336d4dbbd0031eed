#include "tests/support/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace test {
namespace {

bool updating_goldens() {
  const char* value = std::getenv("LIQUID_UPDATE_GOLDENS");
  return value && std::string(value) == "1";
}

}  // namespace

CompareResult compare_images(const engine::vk::Rgba8Image& actual, const engine::vk::Rgba8Image& expected,
                             const CompareTolerance& tolerance) {
  CompareResult result;
  if (actual.width != expected.width || actual.height != expected.height) {
    result.message = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                     " differs from the expected " + std::to_string(expected.width) + "x" +
                     std::to_string(expected.height);
    return result;
  }
  size_t differing = 0;
  const size_t pixels = size_t(actual.width) * actual.height;
  for (size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(int(actual.pixels[i * 4 + c]) - int(expected.pixels[i * 4 + c])));
    result.max_channel_difference = std::max(result.max_channel_difference, worst);
    if (worst > tolerance.channel_threshold) ++differing;
  }
  result.differing_fraction = pixels ? double(differing) / double(pixels) : 0.0;
  result.passed = result.differing_fraction <= tolerance.max_differing_fraction;
  std::ostringstream message;
  message << differing << " of " << pixels << " pixels (" << result.differing_fraction * 100.0
          << "%) differ by more than " << tolerance.channel_threshold << " (allowed "
          << tolerance.max_differing_fraction * 100.0 << "%), largest difference "
          << result.max_channel_difference;
  result.message = message.str();
  return result;
}

CompareResult compare_with_golden(const engine::vk::Rgba8Image& actual, const std::string& name,
                                  const CompareTolerance& tolerance) {
  const std::filesystem::path golden = std::filesystem::path(LIQUID_GOLDEN_DIR) / (name + ".png");
  const std::filesystem::path output_dir = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR);
  if (updating_goldens()) {
    engine::vk::write_png(golden, actual);
    return {true, 0.0, 0, "golden " + golden.string() + " rewritten (LIQUID_UPDATE_GOLDENS=1)"};
  }
  if (!std::filesystem::exists(golden))
    return {false, 1.0, 255,
            "missing golden " + golden.string() + "; run the tests with LIQUID_UPDATE_GOLDENS=1 to create it"};
  const engine::vk::Rgba8Image expected = engine::vk::read_png(golden);
  CompareResult result = compare_images(actual, expected, tolerance);
  if (!result.passed) {
    std::filesystem::create_directories(output_dir);
    const auto actual_path = output_dir / (name + ".actual.png");
    const auto diff_path = output_dir / (name + ".diff.png");
    engine::vk::write_png(actual_path, actual);
    if (actual.width == expected.width && actual.height == expected.height) {
      // Diff image: grey copy of the expected image, differing pixels in red scaled by the error.
      engine::vk::Rgba8Image diff{actual.width, actual.height, std::vector<uint8_t>(actual.pixels.size())};
      for (size_t i = 0; i < actual.pixels.size() / 4; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(int(actual.pixels[i * 4 + c]) - int(expected.pixels[i * 4 + c])));
        const uint8_t grey = uint8_t((expected.pixels[i * 4] + expected.pixels[i * 4 + 1] + expected.pixels[i * 4 + 2]) / 12);
        const bool over = worst > tolerance.channel_threshold;
        diff.pixels[i * 4 + 0] = over ? uint8_t(std::min(255, 128 + worst)) : grey;
        diff.pixels[i * 4 + 1] = over ? 0 : grey;
        diff.pixels[i * 4 + 2] = over ? 0 : grey;
        diff.pixels[i * 4 + 3] = 255;
      }
      engine::vk::write_png(diff_path, diff);
    }
    result.message += "; actual: " + actual_path.string() + ", diff: " + diff_path.string();
  }
  return result;
}

}  // namespace test
