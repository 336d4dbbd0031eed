// PNG files for captured frames and golden images (stb_image_write / stb_image). Writes go to a
// temporary file renamed into place, so a failed or interrupted write never leaves a partial PNG.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace engine::vk {

struct Rgba8Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4, rows top to bottom
};

// Throws std::runtime_error naming the path when it cannot be written.
void write_png(const std::filesystem::path& path, const Rgba8Image& image);
// Throws std::runtime_error naming the path when it is missing or not a PNG.
Rgba8Image read_png(const std::filesystem::path& path);

}  // namespace engine::vk
