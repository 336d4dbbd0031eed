// Secondary particles, spray, foam and bubbles (Scene::whitewater; docs/whitewater.md): their two
// ping-ponged textures and the pass that spawns, classifies and moves them once per step, after the
// particle pass (shaders/liquid/solver/whitewater.frag). Liquid particle i owns the texel at i's
// place in each of `slots_per_particle` blocks of the liquid texture's rows. One-way: no pass of the
// liquid reads these, so the liquid's results are the same with or without them.
#pragma once

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/images.h"
#include "liquid/solver/uniforms.h"
#include "liquid/solver/variant.h"
#include "liquid/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace liquid {

class WhitewaterPass {
 public:
  // Throws DeviceError when the textures (the liquid's width, slots times its height) exceed the
  // device's 2D image limit.
  WhitewaterPass(engine::vk::Context& context, const SolverVariant& variant, const Scene& scene,
                 const SimulationSetup& setup, const std::vector<int32_t>& specialization);

  // The textures imported into this frame's graph: the latest, and the other pair.
  struct Frame {
    WhitewaterImages latest;
    WhitewaterImages targets;
  };
  Frame import(engine::graph::RenderGraph& graph);

  // One step from `frame.latest` into `frame.targets`, then swaps the two: reads the liquid's
  // particles at the step's end and its grids (`step`); `time` is the step's end (s), `step_index`
  // seeds the spawns.
  void add_to(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, const StepImages& step,
              Frame& frame, double time, float dt, int64_t step_index);

  // The live secondary particles (blocking), in slot order, their ages at `time` (s).
  std::vector<WhitewaterParticle> read(double time);
  // Every slot's texels, positions then velocities (blocking): what a checkpoint keeps.
  std::vector<glm::vec4> save();
  // Puts back what save() gave; throws ArgumentError for texels no run makes (a wrong count, a kind
  // outside LIQUID_WHITEWATER_*, a live slot's non-finite value).
  void restore(const std::vector<glm::vec4>& texels);
  // The textures' size, for the capacity (texels).
  glm::ivec2 texture_size() const { return size_; }

 private:
  engine::vk::Context& context_;
  engine::vk::GraphicsPipeline move_;   // moves, classifies and frees the live ones
  engine::vk::GraphicsPipeline spawn_;  // the same, and free slots spawn
  engine::vk::Sampler nearest_;
  engine::vk::Sampler linear_;
  gpu::WhitewaterPush push_{};
  glm::ivec2 size_{0};
  std::array<engine::vk::Image, 2> positions_;   // xyz m, w the kind (LIQUID_WHITEWATER_*)
  std::array<engine::vk::Image, 2> velocities_;  // xyz m/s, w the birth time (s)
  int current_ = 0;
};

}  // namespace liquid
