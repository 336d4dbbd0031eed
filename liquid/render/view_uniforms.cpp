#include "liquid/render/view_uniforms.h"
#include "liquid/solver/node_view.h"

#include <stdexcept>
#include <string>

namespace liquid {

ViewUniforms::ViewUniforms(engine::vk::Context& context, const LiquidNode& node, VkDeviceSize view_block_bytes)
    : node_(node),
      arena_(context,
             engine::vk::UniformArena::frame_bytes({sizeof(gpu::SolverUniforms), view_block_bytes},
                                                   k_max_views_per_frame),
             node.frames_in_flight() + 1) {}

engine::vk::UniformSlice ViewUniforms::begin_frame() {
  const uint64_t frame = node_frames_declared(node_);
  if (frame != frame_) {
    arena_.begin_frame();
    frame_ = frame;
    views_ = 0;
  }
  if (++views_ > k_max_views_per_frame)
    throw UsageError("liquid: more than " + std::to_string(k_max_views_per_frame) +
                     " views of one frame of the node from one renderer");
  return arena_.push(node_uniforms(node_));
}

}  // namespace liquid
