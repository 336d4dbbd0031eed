// Moving image contents between host and device through the graph, so that the copies get their
// barriers from the same Access table as every pass. Used for particle upload, readback of
// diagnostics, frame capture and image tests.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/io/png.h"
#include "engine/vk/buffer.h"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace engine::graph {

// A host-visible buffer a readback pass copies into; valid after the submission completes.
struct Readback {
  std::shared_ptr<vk::Buffer> buffer;
  vk::ImageDesc desc;
  // Tightly packed texels: width * height * depth_or_layers * texel size bytes.
  std::span<const std::byte> bytes() const;
  // The texels as an 8-bit RGBA picture (for PNG output); throws std::logic_error unless the
  // image is R8G8B8A8.
  vk::Rgba8Image rgba8() const;
};

// Adds a pass copying the whole image into a new host-visible buffer.
Readback add_readback(RenderGraph& graph, ImageHandle image, const std::string& pass_name = "readback");

// Adds a pass copying `bytes` (tightly packed, the whole image) into the image; returns its new
// version. The staging buffer lives until the graph's next reset via the pass's record function.
ImageHandle add_upload(RenderGraph& graph, ImageHandle image, std::span<const std::byte> bytes,
                       const std::string& pass_name = "upload");

// Adds a pass copying the whole of `source` into `destination` (same kind, size and format;
// `source` needs VK_IMAGE_USAGE_TRANSFER_SRC_BIT); returns the destination's new version.
ImageHandle add_copy(RenderGraph& graph, ImageHandle source, ImageHandle destination,
                     const std::string& pass_name = "copy");

// Blocking helpers for host code outside a frame: one graph, one submission.
std::vector<std::byte> download_image(vk::Context& context, vk::Image& image);
void upload_image(vk::Context& context, vk::Image& image, std::span<const std::byte> bytes);

}  // namespace engine::graph
