#include "engine/io/png.h"

#include "engine/io/atomic_file.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // internal linkage: no stbi_* symbols clash with a host's own stb
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
// With internal linkage every stb function this file does not call is an unused static one.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include <cstdio>
#include <stdexcept>
#include <string>

namespace engine::vk {

void write_png(const std::filesystem::path& path, const Rgba8Image& image) {
  if (image.pixels.size() != size_t(image.width) * image.height * 4)
    throw std::invalid_argument("write_png: pixel buffer does not match " + std::to_string(image.width) + "x" +
                                std::to_string(image.height));
  std::vector<unsigned char> encoded;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  if (!stbi_write_png_to_func(append, &encoded, int(image.width), int(image.height), 4, image.pixels.data(),
                              int(image.width) * 4))
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  io::write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

Rgba8Image read_png(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
  if (!data) throw std::runtime_error(path.string() + ": cannot read PNG (" + stbi_failure_reason() + ")");
  Rgba8Image image{uint32_t(width), uint32_t(height), std::vector<uint8_t>(data, data + size_t(width) * height * 4)};
  stbi_image_free(data);
  return image;
}

}  // namespace engine::vk
