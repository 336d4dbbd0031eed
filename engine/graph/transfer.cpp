#include "engine/graph/transfer.h"

#include "engine/vk/commands.h"
#include "engine/vk/context.h"

#include <cstring>
#include <stdexcept>

namespace engine::graph {
namespace {

VkDeviceSize image_bytes(const vk::ImageDesc& desc) {
  return VkDeviceSize(desc.width) * desc.height * desc.depth_or_layers * vk::format_texel_size(desc.format);
}

VkBufferImageCopy whole_image_copy(const vk::Image& image) {
  const vk::ImageDesc& d = image.desc();
  VkBufferImageCopy copy{};
  copy.imageSubresource = {image.aspect(), 0, 0, d.kind == vk::ImageKind::Image2DArray ? d.depth_or_layers : 1};
  copy.imageExtent = {d.width, d.height, d.kind == vk::ImageKind::Image3D ? d.depth_or_layers : 1};
  return copy;
}

vk::Context& require_context(RenderGraph& graph, const std::string& pass) {
  if (!graph.context()) throw std::logic_error("render graph: pass '" + pass + "' needs a Vulkan context");
  return *graph.context();
}

}  // namespace

vk::Rgba8Image Readback::rgba8() const {
  if (desc.format != VK_FORMAT_R8G8B8A8_UNORM && desc.format != VK_FORMAT_R8G8B8A8_SRGB)
    throw std::logic_error("Readback::rgba8: the image is not RGBA8");
  const auto texels = bytes();
  vk::Rgba8Image image{desc.width, desc.height, std::vector<uint8_t>(texels.size())};
  std::memcpy(image.pixels.data(), texels.data(), texels.size());
  return image;
}

std::span<const std::byte> Readback::bytes() const {
  buffer->invalidate();
  return {static_cast<const std::byte*>(buffer->mapped()), static_cast<size_t>(image_bytes(desc))};
}

Readback add_readback(RenderGraph& graph, ImageHandle image, const std::string& pass_name) {
  vk::Context& context = require_context(graph, pass_name);
  Readback readback;
  readback.desc = graph.image_desc(image);
  readback.buffer = std::make_shared<vk::Buffer>(context, image_bytes(readback.desc),
                                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                 vk::MemoryUsage::HostVisible, pass_name);
  graph.add_pass(
      pass_name, [&](PassBuilder& builder) { builder.read(image, Access::TransferSource); },
      [image, buffer = readback.buffer](PassContext& ctx) {
        const vk::Image& source = ctx.image(image);
        const VkBufferImageCopy copy = whole_image_copy(source);
        vkCmdCopyImageToBuffer(ctx.cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               buffer->handle(), 1, &copy);
      });
  return readback;
}

ImageHandle add_copy(RenderGraph& graph, ImageHandle source, ImageHandle destination, const std::string& pass_name) {
  const vk::ImageDesc& from = graph.image_desc(source);
  const vk::ImageDesc& to = graph.image_desc(destination);
  if (from.kind != to.kind || from.width != to.width || from.height != to.height ||
      from.depth_or_layers != to.depth_or_layers || from.format != to.format)
    throw std::logic_error("copy '" + pass_name + "': '" + graph.image_name(source) + "' and '" +
                           graph.image_name(destination) + "' differ in kind, size or format");
  struct Data {
    ImageHandle written;
  };
  const Data& data = graph.add_pass<Data>(
      pass_name,
      [&](PassBuilder& builder, Data& d) {
        builder.read(source, Access::TransferSource);
        d.written = builder.write(destination, Access::TransferDestination);
      },
      [source](PassContext& ctx, const Data& d) {
        const vk::Image& from_image = ctx.image(source);
        const vk::Image& to_image = ctx.image(d.written);
        VkImageCopy region{};
        region.srcSubresource = {from_image.aspect(), 0, 0, from_image.full_range().layerCount};
        region.dstSubresource = region.srcSubresource;
        const vk::ImageDesc& desc = from_image.desc();
        region.extent = {desc.width, desc.height, desc.kind == vk::ImageKind::Image3D ? desc.depth_or_layers : 1};
        vkCmdCopyImage(ctx.cmd, from_image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to_image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      });
  return data.written;
}

ImageHandle add_upload(RenderGraph& graph, ImageHandle image, std::span<const std::byte> bytes,
                       const std::string& pass_name) {
  vk::Context& context = require_context(graph, pass_name);
  const VkDeviceSize size = image_bytes(graph.image_desc(image));
  if (bytes.size() != size)
    throw std::invalid_argument("upload '" + pass_name + "': " + std::to_string(bytes.size()) +
                                " bytes for an image of " + std::to_string(size));
  auto staging = std::make_shared<vk::Buffer>(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                              vk::MemoryUsage::HostVisible, pass_name);
  std::memcpy(staging->mapped(), bytes.data(), bytes.size());
  staging->flush();
  struct Data {
    ImageHandle written;
  };
  const Data& data = graph.add_pass<Data>(
      pass_name, [&](PassBuilder& builder, Data& d) { d.written = builder.write(image, Access::TransferDestination); },
      [staging](PassContext& ctx, const Data& d) {
        const vk::Image& target = ctx.image(d.written);
        const VkBufferImageCopy copy = whole_image_copy(target);
        vkCmdCopyBufferToImage(ctx.cmd, staging->handle(), target.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
      });
  return data.written;
}

std::vector<std::byte> download_image(vk::Context& context, vk::Image& image) {
  RenderGraph graph(&context);
  const Readback readback = add_readback(graph, graph.import_image(image.name(), image));
  graph.compile();
  vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  const auto bytes = readback.bytes();
  return {bytes.begin(), bytes.end()};
}

void upload_image(vk::Context& context, vk::Image& image, std::span<const std::byte> bytes) {
  RenderGraph graph(&context);
  add_upload(graph, graph.import_image(image.name(), image), bytes);
  graph.compile();
  vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
}

}  // namespace engine::graph
