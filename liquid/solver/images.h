// The graph images the solver's passes hand each other within a step.
#pragma once

#include "engine/graph/render_graph.h"

namespace liquid {

using engine::graph::ImageHandle;

struct ParticleImages {
  ImageHandle positions;   // RGBA32F, xyz m, w 1 when active
  ImageHandle velocities;  // RGBA32F, xyz m/s
};

struct GridImages {
  ImageHandle velocity;  // (u', fluid flag)
  ImageHandle density;   // rho / rho0
};

}  // namespace liquid
