// What every view does first each frame: start its uniform space and push the solver's block for
// the node's current state (the views share common.glsl's obstacle and grid helpers), sized for
// that block plus the view's own, k_max_views_per_frame times, and for the node's frames in flight.
#pragma once

#include "engine/vk/uniform_arena.h"
#include "liquid/node.h"

namespace liquid {

// Where a view draws: a frame of its own (a full image of RenderSettings' size), or the liquid alone
// into the host's targets (RenderSettings::composite: HostTargets, a HostPanel).
enum class ViewOutput { OwnFrame, HostTargets };

// How many times one renderer may draw a frame of the node (one per view: split screen, a
// reflection), each with its own uniforms.
inline constexpr int k_max_views_per_frame = 4;

class ViewUniforms {
 public:
  // `view_block_bytes`: the size of the view's own uniform block (0 when it has none).
  ViewUniforms(engine::vk::Context& context, const LiquidNode& node, VkDeviceSize view_block_bytes);

  // Starts the frame's region the first time a view of the node's newest frame is drawn (later
  // views of that frame share it); returns the solver block of the node's current state. Throws
  // UsageError past k_max_views_per_frame views of one frame.
  engine::vk::UniformSlice begin_frame();
  // The view's own block for this frame.
  template <class T>
  engine::vk::UniformSlice push(const T& block) {
    return arena_.push(block);
  }

 private:
  const LiquidNode& node_;
  engine::vk::UniformArena arena_;
  uint64_t frame_ = ~uint64_t(0);  // the node's frame the region holds
  int views_ = 0;                  // views drawn of it
};

}  // namespace liquid
