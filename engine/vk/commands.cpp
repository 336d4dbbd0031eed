#include "engine/vk/commands.h"

#include "engine/vk/context.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_helpers.h"

#include <cstdint>

namespace engine::vk {

CommandBuffer::CommandBuffer(Context& context) : context_(context) {
  // Reused when the context has one to spare: see Context::RecycledCommands.
  if (const Context::RecycledCommands spare = context.take_recycled_commands(); spare.cmd) {
    cmd_ = spare.cmd;
    fence_ = spare.fence;
    return;
  }
  cmd_ = allocate_command_buffer(context);
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  const VkResult result = vkCreateFence(context.device(), &fence, nullptr, &fence_);
  if (result != VK_SUCCESS) {
    vkFreeCommandBuffers(context.device(), context.command_pool(), 1, &cmd_);
    VK_CHECK(result);
  }
}

CommandBuffer::~CommandBuffer() {
  if (pending_) vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX);
  context_.recycle_commands({cmd_, fence_});
}

VkCommandBuffer CommandBuffer::begin() {
  wait();
  begin_one_time(cmd_);
  return cmd_;
}

void CommandBuffer::submit() {
  VK_CHECK(vkEndCommandBuffer(cmd_));
  VK_CHECK(vkResetFences(context_.device(), 1, &fence_));
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = cmd_;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  VK_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, fence_));
  pending_ = true;
}

void CommandBuffer::wait() {
  if (!pending_) return;
  VK_CHECK(vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
  pending_ = false;
}

bool CommandBuffer::finished() const {
  if (!pending_) return true;
  const VkResult status = vkGetFenceStatus(context_.device(), fence_);
  if (status == VK_NOT_READY) return false;
  VK_CHECK(status);
  return true;
}

}  // namespace engine::vk
