// The compiled plan of a render graph as plain data: passes in declared order, the barriers each
// one needs before it runs and its attachments. Tests read it with no GPU; dump() prints it.
#pragma once

#include "engine/graph/access.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace engine::graph {

enum class LoadOp { DontCare, Clear, Load };

struct BarrierPlan {
  uint32_t resource = 0;
  std::string resource_name;
  VkPipelineStageFlags2 src_stages = 0;
  VkAccessFlags2 src_access = 0;
  VkPipelineStageFlags2 dst_stages = 0;
  VkAccessFlags2 dst_access = 0;
  VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

struct AttachmentPlan {
  uint32_t resource = 0;
  Access access = Access::ColorAttachmentWrite;
  LoadOp load = LoadOp::DontCare;
  VkClearValue clear{};
};

struct PassPlan {
  std::string name;
  std::vector<BarrierPlan> barriers;
  std::vector<AttachmentPlan> colors;
  std::optional<AttachmentPlan> depth;
  uint32_t width = 0, height = 0, layers = 0;  // render area; 0 for a pass with no attachment
};

struct Plan {
  std::vector<PassPlan> passes;
  // The text form: one line per pass, one per barrier and attachment.
  std::string dump() const;
};

}  // namespace engine::graph
