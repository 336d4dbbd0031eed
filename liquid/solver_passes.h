// The paper's three steps as raster passes on a render graph. Each imports nothing itself: it
// reads and writes the handles it is given and returns the new versions, so a host (or the
// LiquidNode) chains them, step after step, on its own graph.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver_pipelines.h"

namespace liquid {

using engine::graph::ImageHandle;

struct ParticleImages {
  ImageHandle positions;
  ImageHandle velocities;
};

struct GridImages {
  ImageHandle velocity;  // (u', fluid flag)
  ImageHandle density;   // rho / rho0
};

// Section 3: clears `splat` and accumulates every active particle's kernel into it.
ImageHandle add_splat(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                      const engine::vk::UniformSlice& uniforms, const ParticleImages& particles,
                      ImageHandle splat, int active_particles, float kernel_radius_cells);

// Section 4: pressure, gravity, external forces, obstacles and walls, into `grids`.
GridImages add_grid(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                    const engine::vk::UniformSlice& uniforms, ImageHandle splat, const GridImages& grids);

// Section 5: PIC/FLIP velocity and RK2 position from `current` into `next` (the other texture of
// the ping-pong pair), for the rows holding `active_after` particles.
ParticleImages add_particle_update(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                                   const engine::vk::UniformSlice& uniforms, const ParticleImages& current,
                                   ImageHandle splat, const GridImages& grids, const ParticleImages& next,
                                   int active_after);

}  // namespace liquid
