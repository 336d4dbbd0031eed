// The active region (liquid/solver/active_region.h): a 3D step whose grid passes compute only the
// cells near liquid gives bit for bit the particles of one that computes every cell, on every 3D
// path, with either splat and either pressure force and under the pressure projection (whose
// margin is smaller), with obstacles the liquid has not reached
// (an analytic sphere and a mesh one, whose artificial density makes the splat-adjoint pressure
// non-zero where no liquid is), an emitter adding particles where there were none and a dynamic
// body falling into the pool (its passes read the region's P); and it does trim: the cells it skips
// are the zeros of the cleared targets, where the whole grid writes its gravity step.
#include "engine/graph/render_graph.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace {

// A pool 6 cm deep on the floor of a tank 80 cm tall of 2 cm cells (20 x 40 x 20), a sphere above
// it and a jet from the side; `splat` and `pressure` fill in the two modes.
std::string pool_with_jet(const std::string& splat, const std::string& pressure) {
  return R"({ "name": "active region", "dimension": 3, "domain": [0.4, 0.8, 0.4], "grid_resolution": 40,
    "particle_spacing": 0.01, "density": 1000, "stiffness": 12, "gamma": 5, "kernel_radius_cells": 3,
    "pic_ratio": 0.05, "time_step": 0.0004, "substeps": 20, "splat": ")" +
         splat + R"(", "pressure_force": ")" + pressure + R"(",
    "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.4, 0.06, 0.4] } ],
    "obstacles": [ { "shape": "sphere", "center": [0.25, 0.25, 0.2], "radius": 0.05 } ],
    "emitters": [ { "position": [0.03, 0.3, 0.2], "velocity": [1.5, 0.0, 0.0], "radius": 0.02, "capacity": 400 } ] })";
}

// The same tank with a box of 500 kg/m^3 thrown into the pool (dynamic bodies need the
// splat-adjoint pressure and no meshes).
std::string pool_with_body() {
  return R"({ "name": "active region body", "dimension": 3, "domain": [0.4, 0.8, 0.4], "grid_resolution": 40,
    "particle_spacing": 0.01, "density": 1000, "stiffness": 12, "gamma": 5, "kernel_radius_cells": 3,
    "pic_ratio": 0.05, "time_step": 0.0004, "substeps": 20, "splat": "separable", "pressure_force": "splat_adjoint",
    "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.4, 0.06, 0.4] } ],
    "obstacles": [ { "shape": "box", "center": [0.2, 0.1, 0.2], "half_extent": [0.06, 0.03, 0.06],
                     "rotation": {"axis": [0, 0, 1], "degrees": 10}, "velocity": [0.3, -1.0, 0.0],
                     "dynamic": true, "density": 500 } ] })";
}

struct Run {
  int initial_particles = 0;
  liquid::ParticleSnapshot particles;
  std::vector<glm::vec4> grid_velocity;
  std::vector<liquid::BodyState> bodies;
};

Run run(liquid::GridPath path, const liquid::Scene& scene, bool active_region, int steps) {
  engine::vk::Context& context = test::gpu_for(path);
  liquid::LiquidOptions options = test::options_for(path);
  options.active_region = active_region;
  liquid::LiquidNode node(context, scene, options);
  const int initial = node.active_particles();
  test::run_steps(node, steps);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
  return {initial, node.read_particles(), node.read_grid_velocity(), node.read_bodies()};
}

// Cells whose (u', fluid flag) is exactly zero: skipped by the region (the whole grid writes u' = g dt
// in a cell without liquid).
size_t zero_cells(const std::vector<glm::vec4>& grid) {
  return size_t(std::count(grid.begin(), grid.end(), glm::vec4(0.0f)));
}

}  // namespace

TEMPLATE_TEST_CASE("the active region gives the particles of the whole grid bit for bit, and skips the empty cells",
                   "[gpu][liquid][paths][active_region]", test::GeometryPath, test::VertexLayerPath,
                   test::AtlasPath) {
  struct Mode {
    const char* splat;
    const char* pressure;
    int projection_iterations;
  };
  for (const auto& [splat, pressure, iterations] :
       {Mode{"point_sprite", "chapter", 0}, Mode{"separable", "splat_adjoint", 0}, Mode{"separable", "splat_adjoint", 4}}) {
    INFO(splat << " splat, " << pressure << " pressure, " << iterations << " projection iterations");
    liquid::Scene scene = liquid::parse_scene(pool_with_jet(splat, pressure), "active_region.json");
    scene.projection_iterations = iterations;
    scene.obstacles.push_back(test::mesh_obstacle_of(test::icosphere(0.04f, 2), glm::vec3(0.3f, 0.45f, 0.1f)));
    const int steps = 40;  // the jet crosses about 2.4 cm (a cell) of air, the pool sloshes
    const Run region = run(TestType::path, scene, true, steps);
    const Run whole = run(TestType::path, scene, false, steps);
    REQUIRE(region.particles.positions.size() == whole.particles.positions.size());
    CHECK(region.particles.positions.size() > size_t(region.initial_particles));  // the emitter ran
    CHECK(region.particles.positions == whole.particles.positions);
    CHECK(region.particles.velocities == whole.particles.velocities);
    // The pool fills 3 of 40 rows and its region reaches 9 rows above it at most (the splat-adjoint
    // margin, 2 r + 3), the jet's 9 rows around row 15: the top 15 rows, over a third of the grid,
    // are skipped. The whole grid's zeros are the cells inside the spheres, still.
    const size_t cells = region.grid_velocity.size();
    INFO("cells " << cells << ", zero with the region " << zero_cells(region.grid_velocity) << ", whole grid "
                  << zero_cells(whole.grid_velocity));
    CHECK(zero_cells(region.grid_velocity) > zero_cells(whole.grid_velocity) + cells / 3);
  }
}

TEMPLATE_TEST_CASE("the active region gives the particles and a dynamic body of the whole grid bit for bit",
                   "[gpu][liquid][paths][active_region][bodies]", test::GeometryPath, test::VertexLayerPath,
                   test::AtlasPath) {
  for (const int iterations : {0, 4}) {
    INFO(iterations << " projection iterations");
    liquid::Scene scene = liquid::parse_scene(pool_with_body(), "active_region_body.json");
    scene.projection_iterations = iterations;
    const int steps = 40;  // the box falls 1.6 cm and into the pool, which it pushes aside
    const Run region = run(TestType::path, scene, true, steps);
    const Run whole = run(TestType::path, scene, false, steps);
    REQUIRE(region.particles.positions.size() == whole.particles.positions.size());
    CHECK(region.particles.positions == whole.particles.positions);
    CHECK(region.particles.velocities == whole.particles.velocities);
    REQUIRE(region.bodies.size() == 1);
    REQUIRE(whole.bodies.size() == 1);
    const liquid::BodyState& a = region.bodies[0];
    const liquid::BodyState& b = whole.bodies[0];
    INFO("the body's centre " << a.pose.center.y << " m with the region, " << b.pose.center.y << " m whole; force "
                              << a.force.y << " N, " << b.force.y << " N");
    CHECK(a.force.y != 0.0f);  // the liquid acts on it
    CHECK(a.pose.center == b.pose.center);
    CHECK(a.pose.orientation == b.pose.orientation);
    CHECK(a.pose.velocity == b.pose.velocity);
    CHECK(a.pose.angular_velocity == b.pose.angular_velocity);
    CHECK(a.force == b.force);
    CHECK(a.torque == b.torque);
    const size_t cells = region.grid_velocity.size();
    CHECK(zero_cells(region.grid_velocity) > zero_cells(whole.grid_velocity) + cells / 3);  // it trims
  }
}
