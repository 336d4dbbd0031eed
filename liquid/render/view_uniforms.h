// What every view does first each frame: start its uniform space and push the solver's block for
// the node's current state (the views share common.glsl's obstacle and grid helpers), sized for
// that block plus the view's own and for the node's frames in flight.
#pragma once

#include "engine/vk/uniform_arena.h"
#include "liquid/node.h"

namespace liquid {

class ViewUniforms {
 public:
  // `view_block_bytes`: the size of the view's own uniform block (0 when it has none).
  ViewUniforms(engine::vk::Context& context, const LiquidNode& node, VkDeviceSize view_block_bytes);

  // Starts the frame; returns the solver block of the node's current state.
  engine::vk::UniformSlice begin_frame();
  // The view's own block for this frame.
  template <class T>
  engine::vk::UniformSlice push(const T& block) {
    return arena_.push(block);
  }

 private:
  const LiquidNode& node_;
  engine::vk::UniformArena arena_;
};

}  // namespace liquid
