// A primary command buffer with its fence: begin, record, submit, wait. Tools and tests run one
// frame at a time; an engine with frames in flight keeps one of these per frame.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace engine::vk {

class Context;

class CommandBuffer {
 public:
  explicit CommandBuffer(Context& context);
  ~CommandBuffer();
  CommandBuffer(const CommandBuffer&) = delete;
  CommandBuffer& operator=(const CommandBuffer&) = delete;

  // Waits for the previous submission (if any), resets and begins recording.
  VkCommandBuffer begin();
  // Ends recording and submits; wait() blocks until the GPU has finished it.
  void submit();
  void wait();
  // Whether the last submission has finished (true when nothing is pending); does not block.
  bool finished() const;
  void submit_and_wait() {
    submit();
    wait();
  }
  VkCommandBuffer handle() const { return cmd_; }

 private:
  Context& context_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
};

}  // namespace engine::vk
