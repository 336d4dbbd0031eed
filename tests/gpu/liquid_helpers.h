// Helpers for the liquid GPU tests: load a shipped scene, run a node for some steps on a graph
// (checking validation after every frame), and measure what the physics tests need.
#pragma once

#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "liquid/solver/simulation.h"
#include "tests/support/gpu.h"

#include <string>

namespace test {

inline liquid::Scene shipped_scene(const std::string& name) {
  return liquid::load_scene(std::string(LIQUID_ASSET_DIR) + "/scenes/" + name + ".json");
}

// A shipped scene under the equation of state instead of the pressure projection it ships with,
// with the PIC share it shipped with before (`pic_ratio`, per its reference step): for the tests of
// that model (its stiffness, its acoustic steps, its damping).
inline liquid::Scene under_equation_of_state(liquid::Scene scene, float pic_ratio) {
  scene.projection_iterations = 0;
  scene.pic_ratio = pic_ratio;
  return scene;
}

// The chapter's model, named (the library's default is the shipped physical scenes' projection on
// the separable splat): its pressure, its point-sprite splat, its PIC share, no projection.
inline liquid::Scene with_chapter_model(liquid::Scene scene) {
  scene.pressure_force = liquid::PressureForce::Chapter;
  scene.splat = liquid::SplatMode::PointSprite;
  scene.projection_iterations = 0;
  scene.pic_ratio = liquid::k_chapter_pic_ratio;
  return scene;
}

// A 0.32 m box of 16 cells with no gravity and one particle at `at` moving at (0.5, -0.25, 0.125)
// m/s, in the chapter's model: the splat tests' scene.
inline liquid::Scene single_particle_scene(int dimension, glm::vec3 at) {
  liquid::Scene scene = with_chapter_model({});
  scene.name = "single_particle";
  scene.dimension = dimension;
  scene.domain = glm::vec3(0.32f);
  scene.grid_resolution = 16;
  scene.particle_spacing = 0.004f;
  scene.gravity = glm::vec3(0.0f);
  scene.substeps = 1;
  scene.fluid_blocks.push_back({at - glm::vec3(0.0025f), at + glm::vec3(0.0025f), glm::vec3(0.5f, -0.25f, 0.125f)});
  return scene;
}

// `graph` reset, filled by `add` and run in one submission of `cmd`, waited for.
template <class Add>
void run_graph(engine::graph::RenderGraph& graph, engine::vk::CommandBuffer& cmd, Add add) {
  graph.reset();
  add();
  graph.compile();
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
}

// One frame of `steps` steps of `node` on `graph`, run in one submission of `cmd`.
inline void run_frame(liquid::LiquidNode& node, engine::graph::RenderGraph& graph, engine::vk::CommandBuffer& cmd,
                      int steps) {
  run_graph(graph, cmd, [&] { node.add_to(graph, steps); });
}

// Runs `steps` steps in frames of the scene's substeps; returns the last diagnostics.
inline liquid::Diagnostics run_steps(liquid::LiquidNode& node, int steps) {
  engine::vk::Context& context = node.context();
  engine::graph::RenderGraph graph(&context);
  engine::vk::CommandBuffer cmd(context);
  int done = 0;
  while (done < steps) {
    const int n = std::min(node.substeps(), steps - done);
    run_frame(node, graph, cmd, n);
    done += n;
  }
  return node.diagnose();
}

// What every run must keep: the particle count and mass, finite positions inside the domain and
// outside every obstacle, and a bounded density.
inline void require_conserved(liquid::LiquidNode& node, const liquid::Diagnostics& d, int expected_count) {
  INFO("step " << d.step << ": active " << d.active_particles << ", outside " << d.outside_domain << ", inside obstacles "
                << d.inside_obstacles << ", non-finite " << d.non_finite << ", max rho/rho0 " << d.max_density_ratio
                << ", KE " << d.kinetic_energy << " J");
  CHECK(d.active_particles == expected_count);
  CHECK(d.mass == Approx(expected_count * double(simulation_of(node).setup().particle_mass)));
  CHECK(d.non_finite == 0);
  CHECK(d.outside_domain == 0);
  CHECK(d.inside_obstacles == 0);
  CHECK(d.max_density_ratio < 3.0f);
}

// The 3D paths as types, for TEMPLATE_TEST_CASE: each test runs once per path, on a context whose
// device has only the feature that path needs (the atlas none), so the validation layer reports any
// use of the others.
struct GeometryPath {
  static constexpr liquid::GridPath path = liquid::GridPath::GeometryShader;
};
struct VertexLayerPath {
  static constexpr liquid::GridPath path = liquid::GridPath::VertexLayer;
};
struct AtlasPath {
  static constexpr liquid::GridPath path = liquid::GridPath::Atlas;
};

inline engine::vk::Context& gpu_for(liquid::GridPath path) {
  return gpu_with({.geometry_shader = path == liquid::GridPath::GeometryShader,
                   .vertex_layer_output = path == liquid::GridPath::VertexLayer});
}

// Options that force `path` (the contexts above would also choose it unforced).
inline liquid::LiquidOptions options_for(liquid::GridPath path, liquid::LiquidOptions options = {}) {
  options.grid_path = path;
  return options;
}

}  // namespace test
