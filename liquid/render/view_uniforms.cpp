#include "liquid/render/view_uniforms.h"
#include "liquid/solver/simulation.h"

namespace liquid {

ViewUniforms::ViewUniforms(engine::vk::Context& context, const LiquidNode& node, VkDeviceSize view_block_bytes)
    : node_(node),
      arena_(context, engine::vk::UniformArena::frame_bytes({sizeof(gpu::SolverUniforms), view_block_bytes}),
             node.frames_in_flight() + 1) {}

engine::vk::UniformSlice ViewUniforms::begin_frame() {
  arena_.begin_frame();
  return arena_.push(node_.simulation().current_uniforms());
}

}  // namespace liquid
