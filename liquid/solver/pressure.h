// The splat-adjoint pressure (scene key "pressure_force": "splat_adjoint"): two full-screen grid
// passes before the grid pass. The first writes every cell's pressure P (pressure.frag); the second
// smooths it with the splat's own kernel into Phi = W^T P (potential.frag), whose gradient the grid
// pass takes instead of P's. That makes the pressure force the gradient of the liquid's internal
// energy, which the chapter's gradient of P is not (docs/physics.md).
// Shaders: shaders/liquid/solver/pressure.frag and potential.frag.
#pragma once

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/images.h"

#include <cstdint>
#include <vector>

namespace liquid {

// R32F: the cells' pressure and its smoothed potential, m^2/s^2.
constexpr VkFormat k_pressure_format = VK_FORMAT_R32_SFLOAT;

class PressurePass {
 public:
  PressurePass(engine::vk::Context& context, const GridLayout& layout, const std::vector<int32_t>& specialization);

  // Grid-sized descriptions of the two intermediate images (the node creates them as transients).
  engine::vk::ImageDesc image_desc() const { return desc_; }

  // Reads `splat`, writes P into `pressure` and Phi into `potential` (both handles are advanced to
  // their new versions); returns Phi.
  ImageHandle add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, ImageHandle splat,
                     ImageHandle& pressure, ImageHandle& potential) const;

 private:
  engine::vk::GraphicsPipeline pressure_;
  engine::vk::GraphicsPipeline potential_;
  engine::vk::Sampler nearest_;
  engine::vk::ImageDesc desc_;
};

}  // namespace liquid
