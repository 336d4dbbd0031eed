// The graph images the solver's passes hand each other within a step, and the engine names every
// pass of liquid/ (solver and views) declares itself with.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/pipeline.h"

namespace liquid {

using engine::graph::Access;
using engine::graph::ImageHandle;
using engine::graph::PassBuilder;
using engine::graph::PassContext;
using engine::vk::DescriptorKind;

struct ParticleImages {
  ImageHandle positions;   // RGBA32F, xyz m, w 1 when active
  ImageHandle velocities;  // RGBA32F, xyz m/s
};

struct GridImages {
  ImageHandle velocity;  // (u', fluid flag)
  ImageHandle density;   // rho / rho0
};

}  // namespace liquid
