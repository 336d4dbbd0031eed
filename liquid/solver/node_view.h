// What the library's views (liquid/render/) and exports read of a node's solver, and all they
// read: its derived setup, the grid's layout, the solver block of its current state and how many
// frames the node has declared. The Simulation itself stays out of their reach (simulation.h).
#pragma once

#include "liquid/node.h"
#include "liquid/physics/setup.h"
#include "liquid/solver/gpu_types.h"
#include "liquid/solver/grid_layout.h"

#include <cstdint>

namespace liquid {

const SimulationSetup& node_setup(const LiquidNode& node);
const GridLayout& node_grid_layout(const LiquidNode& node);
// The solver's uniform block for the current state with no step in progress (obstacle poses at the
// node's time): what the views read with their own blocks.
gpu::SolverUniforms node_uniforms(const LiquidNode& node);
// How many frames the node has declared: the views start their uniform space once per frame.
uint64_t node_frames_declared(const LiquidNode& node);

}  // namespace liquid
