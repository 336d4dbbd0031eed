// One Access value per use of an image implies the pipeline stages, the access mask, the layout
// and the usage flag together (after kajiya's access types). Passes never write a stage or an
// access mask by hand: the graph derives every barrier from these.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace engine::graph {

enum class Access {
  ColorAttachmentWrite,  // rendered into, every covered texel overwritten
  ColorAttachmentBlend,  // rendered into with blending: reads and writes the attachment
  DepthAttachmentWrite,  // depth test and write
  VertexSampled,         // read by a vertex shader (texelFetch or sample)
  GeometrySampled,       // read by a geometry shader
  FragmentSampled,       // read by a fragment shader
  TransferSource,        // copied from (readback)
  TransferDestination,   // copied into (upload)
};

struct AccessInfo {
  VkPipelineStageFlags2 stages;
  VkAccessFlags2 access;
  VkImageLayout layout;
  VkImageUsageFlags usage;
  bool writes;
  bool attachment;
  const char* name;
};

const AccessInfo& access_info(Access access);
// The layout of `access` on an image of `format`: the table's, except a depth attachment of a
// format with stencil, DEPTH_STENCIL_ATTACHMENT_OPTIMAL.
VkImageLayout access_layout(Access access, VkFormat format);

// Readable names for plan dumps and error messages.
std::string stage_names(VkPipelineStageFlags2 stages);
std::string access_names(VkAccessFlags2 access);
const char* layout_name(VkImageLayout layout);

}  // namespace engine::graph
