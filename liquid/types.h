// The value types of the LiquidNode's API, in one place: what a host passes in (options, force
// brushes, obstacle poses) and what it gets back (graph images, particles, diagnostics).
#pragma once

#include "engine/graph/render_graph.h"
#include "liquid/grid_layout.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace liquid {

// How a node is created for a host's frame loop.
struct LiquidOptions {
  uint32_t frames_in_flight = 2;  // frames the GPU may still be running when add_to() is called
  int max_steps_per_frame = 0;    // 0 = the scene's substeps (uniform space is sized for this)
  double energy_bound_factor = 20.0;
  // How 3D grids are stored and rendered into (liquid/grid_layout.h). Empty: the environment
  // variable LIQUID_3D_PATH (geometry, vertex-layer or atlas) if set, else the best the device has.
  std::optional<GridPath> grid_path;
  // Where the node says, once, which 3D path and splat format it chose when that is worth knowing
  // ("liquid: 3D path: ..."); no sink, no messages.
  std::function<void(const std::string&)> log;
};

// An external force brush (the paper's f_ext): an acceleration (m/s^2) at `position` falling
// smoothly to zero at `radius`. A host maps mouse drags or gameplay forces to these.
struct ForceBrush {
  glm::vec3 position{0.0f};      // m
  float radius = 0.1f;           // m
  glm::vec3 acceleration{0.0f};  // m/s^2
};

// An obstacle's placement at one instant.
struct ObstaclePose {
  glm::vec3 center{0.0f};    // m
  glm::vec3 velocity{0.0f};  // m/s
};

// The graph images after the steps add_to() declared; valid for the rest of that graph. The grids
// are 3D images in 3D, or 2D atlases of their slices on the atlas path (LiquidNode::grid_layout()).
struct LiquidImages {
  engine::graph::ImageHandle positions;      // RGBA32F particle texture, xyz m
  engine::graph::ImageHandle velocities;     // RGBA32F particle texture, xyz m/s
  engine::graph::ImageHandle splat;          // (sum w u, sum w), the last step's splat
  engine::graph::ImageHandle grid_velocity;  // (u', fluid flag)
  engine::graph::ImageHandle density;        // R16F rho / rho0
};

// Particles read back from the GPU.
struct ParticleSnapshot {
  std::vector<glm::vec4> positions;   // active particles only
  std::vector<glm::vec4> velocities;
};

// Per-step health of a simulation: what the physics must conserve and respect (count and mass,
// finite state, walls and obstacles not crossed) and energy.
struct Diagnostics {
  int step = 0;
  double time = 0.0;               // s
  int active_particles = 0;
  int outside_domain = 0;          // particles beyond a wall
  int inside_obstacles = 0;        // particles inside an obstacle (signed distance < 0)
  int non_finite = 0;              // particles with a NaN or Inf component
  float max_density_ratio = 0.0f;  // max rho / rho0 over the grid
  double mass = 0.0;               // kg, active particles * particle mass
  double kinetic_energy = 0.0;     // J, sum 1/2 m |u|^2
  // J, sum m |g| (height above the domain's lowest point along gravity): zero for liquid lying on
  // the floor, so its share of the mechanical energy is the part gravity can still release.
  double potential_energy = 0.0;
  double mechanical_energy = 0.0;  // J, kinetic + potential
  double time_step = 0.0;          // s, the last step's dt
  float max_speed = 0.0f;          // m/s
  glm::vec3 center_of_mass{0.0f};  // m
};

}  // namespace liquid
