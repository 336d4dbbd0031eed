// Mesh obstacles on the GPU (liquid/solver/mesh_field.h): the rasterizer's field against the
// analytic distance of the sphere the mesh approximates on every 3D path and in 2D, no particle
// left inside a mesh after its first step, and a mesh sphere stirring a pool as the analytic
// sphere on the same path does.
#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace {

// A 32^3 grid of 1 cm cells with a little liquid in a corner, for the field alone.
const char* k_field_3d = R"({
  "name": "mesh field 3D", "dimension": 3, "domain": [0.32, 0.32, 0.32], "grid_resolution": 32,
  "particle_spacing": 0.01, "stiffness": 9.8, "kernel_radius_cells": 3, "time_step": 0.0005, "substeps": 1,
  "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.06, 0.06, 0.06] } ] })";
const char* k_field_2d = R"({
  "name": "mesh field 2D", "dimension": 2, "domain": [0.32, 0.32], "grid_resolution": 32,
  "particle_spacing": 0.005, "stiffness": 9.8, "kernel_radius_cells": 3, "time_step": 0.0005, "substeps": 1,
  "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.06, 0.06] } ] })";

void run_frame(liquid::LiquidNode& node, int steps) {
  engine::graph::RenderGraph graph(&node.context());
  engine::vk::CommandBuffer cmd(node.context());
  node.add_to(graph, steps);
  graph.compile();
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
}

// The field of a mesh sphere of `radius` at `center` against |p - c| - radius: the cells within
// the seed band (where the field is exact) within the facets' own error, a fiftieth of a cell, the
// rest of the band (the jump flood's) within a quarter cell, every cell's sign right, the clamp
// beyond the band.
void check_sphere_field(liquid::LiquidNode& node, glm::vec3 center, float radius, float near_tolerance_cells = 0.02f) {
  liquid::Simulation& sim = simulation_of(node);
  REQUIRE(sim.mesh_field() != nullptr);
  const std::vector<glm::vec4> field = sim.mesh_field()->read(node.context());
  const float h = node.cell_size(), band = sim.mesh_field()->band();
  const glm::ivec3 n = node.grid_cells();
  const float seed_band = liquid::gpu::k_mesh_seed_cells * h;
  float worst = 0.0f, worst_at = 0.0f, worst_near = 0.0f;
  int wrong_sign = 0, compared = 0;
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) {
        glm::vec3 p = (glm::vec3(x, y, z) + 0.5f) * h;
        if (node.dimension() == 2) p.z = 0.0f;
        const float exact = glm::length(p - center) - radius;
        const float d = field[size_t(x) + size_t(n.x) * (size_t(y) + size_t(n.y) * z)].x;
        if (std::abs(exact) > 0.1f * h && (d < 0.0f) != (exact < 0.0f)) ++wrong_sign;
        if (std::abs(exact) < band - 0.1f * h) {
          if (std::abs(exact) < seed_band - 0.1f * h) worst_near = std::max(worst_near, std::abs(d - exact));
          if (std::abs(d - exact) > worst) {
            worst = std::abs(d - exact);
            worst_at = exact;
          }
          ++compared;
        } else if (std::abs(exact) > band + 0.1f * h && std::abs(d) < band * 0.999f) {
          ++wrong_sign;  // beyond the band the field holds the clamp
        }
      }
  INFO("cells compared " << compared << ", worst |field - exact| " << worst / h << " cells (where the exact distance is "
                         << worst_at / h << " cells), within the seed band " << worst_near / h
                         << " cells, wrong sign or clamp " << wrong_sign);
  CHECK(compared > 100);
  CHECK(wrong_sign == 0);
  CHECK(worst_near < near_tolerance_cells * h);
  CHECK(worst < 0.25f * h);
}

// The scene's analytic sphere and a mesh sphere of the same radius on the same path: the centre of
// mass within half a cell and the kinetic energy within 5 % every 0.25 s for 2 s.
void compare_stirring(const char* json) {
  engine::vk::Context& context = test::gpu();
  const liquid::Scene analytic = liquid::parse_scene(json, "stirred_pool.json");
  liquid::Scene meshed = analytic;
  liquid::Obstacle& o = meshed.obstacles[0];
  o.shape = liquid::ObstacleShape::Mesh;
  o.mesh = test::icosphere(o.radius, 4);
  liquid::LiquidNode a(context, analytic), m(context, meshed);
  // The lattice is carved around each (liquid/physics/setup.cpp): the mesh's faces lie up to 0.1 %
  // of the radius inside the sphere, which can keep a few more lattice points.
  INFO("particles: analytic " << a.active_particles() << ", mesh " << m.active_particles());
  REQUIRE(std::abs(a.active_particles() - m.active_particles()) <= a.active_particles() / 200);
  const float h = a.cell_size();
  double worst_com = 0.0, worst_energy = 0.0, peak_energy = 0.0;
  const int steps_per_sample = int(std::lround(0.25 / a.time_step()));
  for (int sample = 1; sample <= 8; ++sample) {
    for (liquid::LiquidNode* node : {&a, &m})
      for (int done = 0; done < steps_per_sample; done += node->substeps())
        run_frame(*node, std::min(node->substeps(), steps_per_sample - done));
    const liquid::Diagnostics da = a.diagnose(), dm = m.diagnose();
    const double com = glm::length(da.center_of_mass - dm.center_of_mass);
    const double energy = std::abs(dm.kinetic_energy - da.kinetic_energy) / da.kinetic_energy;
    UNSCOPED_INFO("t = " << a.time() << " s: centre of mass apart " << com / h << " cells, kinetic energy "
                         << da.kinetic_energy << " / " << dm.kinetic_energy << " J (analytic / mesh), "
                         << 100.0 * energy << " %; inside " << da.inside_obstacles << " / " << dm.inside_obstacles);
    worst_com = std::max(worst_com, com);
    worst_energy = std::max(worst_energy, energy);
    peak_energy = std::max(peak_energy, da.kinetic_energy);
    CHECK(dm.inside_obstacles == 0);
  }
  CHECK(peak_energy > 1e-3);  // the sphere did stir the pool
  CHECK(worst_com < 0.5 * h);
  CHECK(worst_energy < 0.05);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

// Each 3D path (or 2D) with a mesh sphere teleported into a pool: particles inside before the
// step, none after it.
liquid::Scene pool_with_mesh_sphere(int dimension) {
  liquid::Scene scene = liquid::parse_scene(
      dimension == 3 ? R"({ "name": "mesh pool 3D", "dimension": 3, "domain": [0.3, 0.24, 0.2], "grid_resolution": 15,
        "particle_spacing": 0.01, "stiffness": 9.8, "kernel_radius_cells": 3, "pic_ratio": 0.1,
        "pressure_force": "splat_adjoint", "time_step": 0.0004, "substeps": 1, "wall_margin_cells": 0.25,
        "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.3, 0.1, 0.2] } ] })"
                     : R"({ "name": "mesh pool 2D", "dimension": 2, "domain": [0.3, 0.24], "grid_resolution": 30,
        "particle_spacing": 0.005, "stiffness": 9.8, "kernel_radius_cells": 3, "pic_ratio": 0.1,
        "pressure_force": "splat_adjoint", "time_step": 0.0004, "substeps": 1, "wall_margin_cells": 0.25,
        "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.3, 0.1] } ] })",
      "mesh_pool.json");
  // Above the water at the start (nothing carved), then placed in it.
  scene.obstacles.push_back(test::mesh_obstacle_of(test::icosphere(0.045f, 2), glm::vec3(0.15f, 0.18f, 0.0f)));
  if (dimension == 3) scene.obstacles.back().center.z = 0.1f;
  return scene;
}

void check_pushed_out(liquid::LiquidNode& node) {
  // Its bottom 2 cm above the floor: the liquid under it has room to leave.
  const glm::vec3 in_water = node.dimension() == 3 ? glm::vec3(0.15f, 0.065f, 0.1f) : glm::vec3(0.15f, 0.065f, 0.0f);
  node.set_obstacle_pose(0, in_water, glm::vec3(0.0f));
  const liquid::Diagnostics before = node.diagnose();
  run_frame(node, 1);
  const liquid::Diagnostics after = node.diagnose();
  INFO("particles inside the mesh: " << before.inside_obstacles << " before its first step there, "
                                     << after.inside_obstacles << " after");
  CHECK(before.inside_obstacles > 50);
  CHECK(after.inside_obstacles == 0);
  CHECK(after.outside_domain == 0);
}

}  // namespace

TEMPLATE_TEST_CASE("each 3D path voxelizes a mesh sphere within a quarter cell of the sphere's distance",
                   "[gpu][liquid][mesh][paths]", test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::Scene scene = liquid::parse_scene(k_field_3d, "mesh_field_3d.json");
  const glm::vec3 center(0.17f, 0.155f, 0.162f);  // off the cell centres
  const float radius = 0.08f;
  scene.obstacles.push_back(test::mesh_obstacle_of(test::icosphere(radius, 4), center));
  liquid::LiquidNode node(context, scene, test::options_for(TestType::path));
  run_frame(node, 1);
  CHECK(simulation_of(node).mesh_field()->voxelizations() == 1);
  check_sphere_field(node, center, radius);
  run_frame(node, 1);  // it stands still: not voxelized again
  CHECK(simulation_of(node).mesh_field()->voxelizations() == 1);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

// A mesh that fits in the grid is voxelized once, into its reference field, and placed at each
// pose by the resample pass: moved by a fraction of a cell and turned, its field stays within the
// interpolation's error of the sphere's distance with no new voxelization; a new scale voxelizes it again.
TEMPLATE_TEST_CASE("each 3D path places a mesh's reference field at a new pose without voxelizing it again",
                   "[gpu][liquid][mesh][paths]", test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::Scene scene = liquid::parse_scene(k_field_3d, "mesh_field_3d.json");
  const float radius = 0.08f;
  scene.obstacles.push_back(test::mesh_obstacle_of(test::icosphere(radius, 4), glm::vec3(0.17f, 0.155f, 0.162f)));
  liquid::LiquidNode node(context, scene, test::options_for(TestType::path));
  const liquid::MeshField& field = *simulation_of(node).mesh_field();
  REQUIRE(field.resampled(0));
  run_frame(node, 1);
  CHECK(field.triangle_voxelizations() == 1);

  const glm::vec3 moved(0.1537f, 0.1712f, 0.1491f);  // a fraction of a cell off in each axis
  const glm::quat turned = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)));
  node.set_obstacle_pose(0, moved, glm::vec3(0.0f));
  node.set_mesh_transform(0, turned, 1.0f);
  run_frame(node, 1);
  CHECK(field.voxelizations() == 2);
  CHECK(field.triangle_voxelizations() == 1);
  check_sphere_field(node, moved, radius, 0.05f);

  node.set_mesh_transform(0, turned, 1.1f);
  run_frame(node, 1);
  CHECK(field.voxelizations() == 3);
  CHECK(field.triangle_voxelizations() == 2);
  check_sphere_field(node, moved, 1.1f * radius, 0.05f);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("in 2D a mesh sphere's field is its cross-section's distance at z = 0", "[gpu][liquid][mesh]") {
  engine::vk::Context& context = test::gpu();
  liquid::Scene scene = liquid::parse_scene(k_field_2d, "mesh_field_2d.json");
  const glm::vec3 center(0.17f, 0.155f, 0.0f);
  const float radius = 0.08f;
  scene.obstacles.push_back(test::mesh_obstacle_of(test::icosphere(radius, 4), center));
  liquid::LiquidNode node(context, scene);
  run_frame(node, 1);
  check_sphere_field(node, center, radius);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEMPLATE_TEST_CASE("no particle is left inside a mesh obstacle after its first step in the liquid",
                   "[gpu][liquid][mesh][paths]", test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::LiquidNode node(context, pool_with_mesh_sphere(3), test::options_for(TestType::path));
  check_pushed_out(node);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("no particle is left inside a 2D mesh obstacle after its first step in the liquid", "[gpu][liquid][mesh]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, pool_with_mesh_sphere(2));
  check_pushed_out(node);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

// The sphere dragged along a pool for 2 s with a bob of 2 cm at 1 Hz.
TEST_CASE("a mesh sphere moved through a 2D pool stirs it as the analytic sphere on the same path does",
          "[gpu][liquid][mesh]") {
  // The mesh's cross-section at z = 0 is the sphere's circle.
  compare_stirring(R"({ "name": "stirred pool", "dimension": 2, "domain": [0.6, 0.3], "grid_resolution": 48,
      "particle_spacing": 0.00625, "stiffness": 9.8, "kernel_radius_cells": 3, "pic_ratio": 0.1,
      "pic_ratio_reference_step": 0.0002, "pressure_force": "splat_adjoint", "substeps": 25, "wall_margin_cells": 0.25,
      "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.6, 0.12] } ],
      "obstacles": [ { "shape": "sphere", "center": [0.1, 0.1], "radius": 0.05, "velocity": [0.2, 0],
                       "oscillation": { "amplitude": [0, 0.02], "frequency": 1 } } ] })");
}

TEST_CASE("a mesh sphere moved through a 3D pool stirs it as the analytic sphere on the same path does",
          "[gpu][liquid][mesh]") {
  compare_stirring(R"({ "name": "stirred pool 3D", "dimension": 3, "domain": [0.4, 0.25, 0.2], "grid_resolution": 16,
      "particle_spacing": 0.0125, "stiffness": 9.8, "kernel_radius_cells": 3, "pic_ratio": 0.1,
      "pic_ratio_reference_step": 0.0004, "pressure_force": "splat_adjoint", "splat": "separable", "substeps": 25,
      "wall_margin_cells": 0.25, "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.4, 0.1, 0.2] } ],
      "obstacles": [ { "shape": "sphere", "center": [0.1, 0.1, 0.1], "radius": 0.05, "velocity": [0.1, 0, 0],
                       "oscillation": { "amplitude": [0, 0.02, 0], "frequency": 1 } } ] })");
}

namespace {

// A 3D pool 8 cm deep with a mesh paddle (a box 16 cm wide, 4 cm thick, through the water) standing
// in it about the vertical through its centre (the lattice carved around it, the liquid filling in).
liquid::Scene pool_with_paddle(const char* spin) {
  const std::string json = std::string(R"({ "name": "paddle pool", "dimension": 3, "domain": [0.4, 0.16, 0.4],
      "grid_resolution": 20, "particle_spacing": 0.01, "stiffness": 9.8, "kernel_radius_cells": 3, "pic_ratio": 0.1,
      "pic_ratio_reference_step": 0.0004, "pressure_force": "splat_adjoint", "splat": "separable", "substeps": 5,
      "wall_margin_cells": 0.25, "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.4, 0.08, 0.4] } ],
      "obstacles": [ { "shape": "box", "center": [0.2, 0.06, 0.2], "half_extent": [0.08, 0.05, 0.02])") +
                           spin + "} ] }";
  liquid::Scene scene = liquid::parse_scene(json, "paddle_pool.json");
  liquid::Obstacle& o = scene.obstacles[0];
  o.shape = liquid::ObstacleShape::Mesh;
  o.mesh = test::box_mesh(o.half_extent);
  o.mesh.rotation = o.rotation;
  return scene;
}

// The liquid's angular momentum about the vertical through the paddle's centre, kg m^2/s.
double angular_momentum_y(liquid::LiquidNode& node, glm::vec3 axis_point) {
  const liquid::ParticleSnapshot p = simulation_of(node).read_particles();
  double total = 0.0;
  for (size_t i = 0; i < p.positions.size(); ++i)
    total += glm::cross(glm::vec3(p.positions[i]) - axis_point, glm::vec3(p.velocities[i])).y;
  return total * simulation_of(node).setup().particle_mass;
}

// Runs the paddle pool for 0.4 s; `rate` (rad/s about +y) turns the mesh by set_mesh_transform
// before every frame (passing `given` as its angular velocity, if any); returns the liquid's
// angular momentum about the paddle's axis, and checks no particle ends inside it.
double stirred_angular_momentum(liquid::Scene scene, float rate, std::optional<float> given = std::nullopt) {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, scene);
  const glm::vec3 axis_point = scene.obstacles[0].center;
  const int frames = int(std::lround(0.4 / (node.time_step() * node.substeps())));
  for (int frame = 0; frame < frames; ++frame) {
    if (rate != 0.0f) {
      const glm::quat turn = glm::angleAxis(rate * float(node.time()), glm::vec3(0.0f, 1.0f, 0.0f));
      if (given)
        node.set_mesh_transform(0, turn, 1.0f, glm::vec3(0.0f, *given, 0.0f));
      else
        node.set_mesh_transform(0, turn, 1.0f);
    }
    run_frame(node, node.substeps());
  }
  const liquid::Diagnostics d = node.diagnose();
  CHECK(d.inside_obstacles == 0);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
  return angular_momentum_y(node, axis_point);
}

}  // namespace

TEST_CASE("a mesh paddle turned by set_mesh_transform gives the liquid angular momentum in the sense of its turn",
          "[gpu][liquid][mesh]") {
  const liquid::Scene scene = pool_with_paddle("");
  const float rate = 3.0f;  // rad/s about +y
  const double still = stirred_angular_momentum(scene, 0.0f);
  const double forward = stirred_angular_momentum(scene, rate);
  const double backward = stirred_angular_momentum(scene, -rate);
  const double given = stirred_angular_momentum(scene, rate, rate);
  // Scale: the water within the paddle's reach turning with it, |L| ~ rho w (pi R^4 / 2) depth.
  const double reference = 1000.0 * rate * M_PI * std::pow(0.08, 4) / 2.0 * 0.08;
  INFO("angular momentum about the paddle's axis after 0.4 s (kg m^2/s): still " << still << ", turned +" << rate
                                                                                  << " rad/s " << forward << ", turned -"
                                                                                  << rate << " rad/s " << backward
                                                                                  << ", given the rate " << given
                                                                                  << "; reference " << reference);
  WARN("paddle: L still " << still << ", +" << rate << " rad/s " << forward << ", -" << rate << " rad/s " << backward
                           << ", given " << given << " kg m^2/s; reference " << reference);
  CHECK(forward > 0.1 * reference);
  CHECK(backward < -0.1 * reference);
  CHECK(std::abs(forward + backward) < 0.1 * forward);  // the pool is symmetric under the turn's reversal
  CHECK(std::abs(still) < 0.02 * forward);
  CHECK(std::abs(given - forward) < 0.1 * forward);
}

TEST_CASE("a mesh paddle with a scripted spin stirs the liquid as one turned by the host at the same rate",
          "[gpu][liquid][mesh]") {
  const float rate = 3.0f;
  const double scripted = stirred_angular_momentum(pool_with_paddle(R"(, "angular_velocity": [0, 3, 0])"), 0.0f);
  const double hosted = stirred_angular_momentum(pool_with_paddle(""), rate);
  INFO("angular momentum after 0.4 s (kg m^2/s): scripted spin " << scripted << ", turned by the host " << hosted);
  WARN("paddle: L scripted " << scripted << ", host " << hosted);
  CHECK(scripted > 0.0);
  CHECK(std::abs(scripted - hosted) < 0.15 * hosted);
}
