// What the capture tool's caches rest on, on the device: checkpoints that continue a run bit for
// bit, grids rebuilt for the instant a frame is written, and OpenVDB files that hold the node's
// grids (read back through OpenVDB itself).
#include "engine/graph/render_graph.h"
#include "engine/vk/commands.h"
#include "liquid/export/volume.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/gpu.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/vdb.h"
#include "liquid/solver/simulation.h"

#include <array>
#include <fstream>
#include <iterator>
#include <set>
#endif

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace {

// A small 2D scene with everything a checkpoint must carry: a block, a running emitter and a
// moving obstacle (whose pose the test also overrides).
const char* k_scene = R"({
  "dimension": 2, "domain": [0.4, 0.3], "grid_resolution": 32, "particle_spacing": 0.01,
  "stiffness": 12, "time_step": 0.001, "substeps": 5,
  "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.12, 0.15] } ],
  "emitters": [ { "position": [0.3, 0.2], "velocity": [-0.5, 0.0], "radius": 0.02, "capacity": 400 } ],
  "obstacles": [ { "shape": "sphere", "center": [0.25, 0.06], "radius": 0.03, "velocity": [0.1, 0.0] } ]
})";

bool same_bits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)) == 0;
}

// The particles' velocities after a node of `scene` restored from `checkpoint` runs `steps` steps.
std::vector<glm::vec4> velocities_resumed(const liquid::Scene& scene, const liquid::LiquidNode::Checkpoint& checkpoint,
                                          int steps) {
  liquid::LiquidNode node(test::gpu(), scene);
  node.restore_checkpoint(checkpoint);
  test::run_steps(node, steps);
  return node.read_particles().velocities;
}

// Runs one frame that rebuilds the grids of the current particles (no step).
void add_grids(liquid::LiquidNode& node) {
  engine::graph::RenderGraph graph(&test::gpu());
  engine::vk::CommandBuffer cmd(test::gpu());
  node.add_grids_to(graph, node.add_to(graph, 0));
  graph.compile();
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
}

}  // namespace

TEST_CASE("a node restored from a checkpoint continues the run bit for bit", "[gpu][liquid][export]") {
  const liquid::Scene scene = liquid::parse_scene(k_scene, "checkpoint.json");
  liquid::LiquidNode first(test::gpu(), scene);
  test::run_steps(first, 20);
  first.set_obstacle_pose(0, {0.08f, 0.05f, 0.0f}, {0.0f, 0.2f, 0.0f});  // into the liquid: it matters
  test::run_steps(first, 5);
  const liquid::LiquidNode::Checkpoint saved = first.save_checkpoint();
  REQUIRE(saved.emitted.size() == 1);
  REQUIRE(saved.emitted[0] > 0);  // the emitter's count is part of what continues
  REQUIRE(saved.poses[0].overridden);
  test::run_steps(first, 25);
  const liquid::ParticleSnapshot expected = first.read_particles();

  liquid::LiquidNode second(test::gpu(), scene);
  second.restore_checkpoint(saved);
  CHECK(second.step_count() == saved.step);
  CHECK(second.time() == saved.time);
  test::run_steps(second, 25);
  const liquid::ParticleSnapshot resumed = second.read_particles();
  CHECK(second.active_particles() == first.active_particles());
  CHECK(second.time() == first.time());
  CHECK(same_bits(resumed.positions, expected.positions));
  CHECK(same_bits(resumed.velocities, expected.velocities));

  // Without the checkpoint the second node would not match: the test can fail.
  liquid::LiquidNode fresh(test::gpu(), scene);
  test::run_steps(fresh, 50);
  CHECK_FALSE(same_bits(fresh.read_particles().positions, expected.positions));

  liquid::LiquidNode other(test::gpu(), test::shipped_scene("dam_break_2d"));
  CHECK_THROWS_WITH(other.restore_checkpoint(saved), Catch::Contains("does not match this scene"));
  // More active particles than the scene holds: said as such, not as a size mismatch.
  liquid::LiquidNode::Checkpoint crowded = saved;
  crowded.active = int(saved.positions.size()) + 1;
  CHECK_THROWS_WITH(second.restore_checkpoint(crowded),
                    Catch::Contains("holds " + std::to_string(crowded.active) + " active particles, outside the") &&
                        Catch::Contains("capacity"));
  // Every value is held to what a run reaches, naming it (a NaN used to run on into "unstable").
  const auto refused = [&](auto edit, const std::string& message) {
    liquid::LiquidNode::Checkpoint edited = saved;
    edit(edited);
    CHECK_THROWS_WITH(second.restore_checkpoint(edited), Catch::StartsWith("liquid: the checkpoint's " + message));
  };
  refused([](auto& c) { c.positions[3].x = std::nanf(""); }, "particle 3 has a non-finite position or velocity");
  refused([](auto& c) { c.velocities[0].y = INFINITY; }, "particle 0 has a non-finite position or velocity");
  refused([](auto& c) { c.positions[1].y = -0.5f; }, "particle 1 lies outside the domain (-0.5 m on axis 1)");
  refused([](auto& c) { c.time = -1.0; }, "time is not a finite time >= 0 s");
  refused([](auto& c) { c.step = -3; }, "step count is negative (-3)");
  refused([](auto& c) { c.time_step = 1.0; }, "time step is not in [0, 0.001] s");
  refused([](auto& c) { c.emitted[0] = 401; }, "emitter 0 has added 401 particles, outside [0, 400]");
  refused([](auto& c) { c.poses[0].center.x = std::nanf(""); }, "obstacle 0 has a non-finite pose");
  REQUIRE_NO_VALIDATION_MESSAGES();
}


TEST_CASE("under the affine transfer a checkpoint carries the velocity gradients and continues bit for bit",
          "[gpu][liquid][export][affine]") {
  std::string text = k_scene;
  text.replace(text.find("\"substeps\": 5,"), 14, "\"substeps\": 5, \"transfer\": \"affine\", \"splat\": \"point_sprite\",");
  const liquid::Scene scene = liquid::parse_scene(text, "checkpoint.json");
  liquid::LiquidNode first(test::gpu(), scene);
  test::run_steps(first, 25);
  const liquid::LiquidNode::Checkpoint saved = first.save_checkpoint();
  REQUIRE(saved.affine.size() == saved.positions.size());  // one texture of C_p in 2D
  REQUIRE(std::any_of(saved.affine.begin(), saved.affine.end(), [](glm::vec4 c) { return c != glm::vec4(0.0f); }));
  test::run_steps(first, 25);
  const liquid::ParticleSnapshot expected = first.read_particles();

  CHECK(same_bits(velocities_resumed(scene, saved, 25), expected.velocities));
  // The gradients are state: restored as zero, the run differs.
  liquid::LiquidNode::Checkpoint flat = saved;
  std::fill(flat.affine.begin(), flat.affine.end(), glm::vec4(0.0f));
  CHECK_FALSE(same_bits(velocities_resumed(scene, flat, 25), expected.velocities));
  // A checkpoint of the chapter's transfer does not fit.
  liquid::LiquidNode::Checkpoint none = saved;
  none.affine.clear();
  CHECK_THROWS_WITH(first.restore_checkpoint(none), Catch::Contains("does not match this scene"));
  liquid::LiquidNode::Checkpoint broken = saved;
  broken.affine[2].y = std::nanf("");
  CHECK_THROWS_WITH(first.restore_checkpoint(broken),
                    Catch::StartsWith("liquid: the checkpoint's velocity gradients hold a non-finite value (particle 2)"));
  REQUIRE_NO_VALIDATION_MESSAGES();
}
TEST_CASE("under the pressure projection a checkpoint carries its solution, and a view's grids change nothing",
          "[gpu][liquid][export][projection]") {
  std::string text = k_scene;
  text.replace(text.find("\"substeps\": 5,"), 14,
               "\"substeps\": 5, \"pressure_force\": \"splat_adjoint\", \"projection_iterations\": 8,");
  const size_t obstacles = text.find(",\n  \"obstacles\"");  // the projection takes none yet
  text.erase(obstacles, text.rfind("\n}") - obstacles);
  const liquid::Scene scene = liquid::parse_scene(text, "checkpoint.json");
  liquid::LiquidNode first(test::gpu(), scene);
  test::run_steps(first, 25);
  const liquid::LiquidNode::Checkpoint saved = first.save_checkpoint();
  REQUIRE(saved.pressure.size() == 2u * 32u * 24u);  // the grid's cells' (p, psi)
  REQUIRE(std::any_of(saved.pressure.begin(), saved.pressure.end(), [](float p) { return p > 0.0f; }));
  add_grids(first);  // what a view asks for between two frames
  test::run_steps(first, 25);
  const liquid::ParticleSnapshot expected = first.read_particles();

  CHECK(same_bits(velocities_resumed(scene, saved, 25), expected.velocities));
  // The solution is state: restored as zero, the run differs.
  liquid::LiquidNode::Checkpoint flat = saved;
  std::fill(flat.pressure.begin(), flat.pressure.end(), 0.0f);
  CHECK_FALSE(same_bits(velocities_resumed(scene, flat, 25), expected.velocities));
  liquid::LiquidNode::Checkpoint none = saved;
  none.pressure.clear();
  CHECK_THROWS_WITH(first.restore_checkpoint(none), Catch::Contains("does not match this scene"));
  liquid::LiquidNode::Checkpoint broken = saved;
  broken.pressure[5] = std::nanf("");  // texel 2's psi
  CHECK_THROWS_WITH(first.restore_checkpoint(broken),
                    Catch::StartsWith("liquid: the checkpoint's pressure holds a non-finite value (texel 2)"));
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("grids rebuilt from the particles read the rest density of the initial lattice", "[gpu][liquid][export]") {
  liquid::LiquidNode node(test::gpu(), test::shipped_scene("rest_pool_2d"));
  liquid::VolumeFrame before = liquid::read_volume(test::gpu(), node);
  CHECK(*std::max_element(before.density.begin(), before.density.end()) == 0.0f);  // no step: empty grids
  add_grids(node);
  CHECK(node.step_count() == 0);
  const liquid::VolumeFrame volume = liquid::read_volume(test::gpu(), node);
  const liquid::ParticleSnapshot particles = node.read_particles();
  const std::vector<float> density = liquid::sample_density(volume, particles.positions);
  std::vector<float> sorted = density;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted[sorted.size() / 2] == Approx(1.0f).margin(0.05f));  // inside the pool: rho0
  CHECK(sorted.front() < 0.8f);                                     // at the free surface: less
  REQUIRE_NO_VALIDATION_MESSAGES();
}

#if RASTERLIQUIDS_HAVE_OPENVDB
TEST_CASE("OpenVDB files hold the node's density and velocity grids in metres", "[gpu][liquid][export][paths]") {
  // 3D on every path: the atlas's read-back is converted to the same cell order.
  using liquid::GridPath;
  struct Case {
    const char* name;
    GridPath path;
  };
  for (const Case c : {Case{"small_3d", GridPath::GeometryShader}, Case{"small_3d", GridPath::VertexLayer},
                       Case{"small_3d", GridPath::Atlas}, Case{"dam_break_2d", GridPath::Atlas}}) {
    const std::string name = std::string(c.name) + "_" + liquid::grid_path_name(c.path);
    INFO(name);
    engine::vk::Context& context = test::gpu_for(c.path);
    liquid::LiquidNode node(context, test::shipped_scene(c.name), test::options_for(c.path));
    test::run_steps(node, 10);
    const liquid::VolumeFrame volume = liquid::read_volume(context, node);
    const std::filesystem::path path = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / ("volume_" + name + ".vdb");
    std::filesystem::create_directories(path.parent_path());
    liquid::write_vdb(path, volume, liquid::VdbFrame{7, node.time(), node.scene().name});
    const liquid::VdbContents file = liquid::read_vdb(path);

    CHECK(file.grid_names == std::vector<std::string>{"density", "velocity"});
    CHECK(file.frame.frame == 7);
    CHECK(file.frame.time_s == node.time());
    CHECK(file.voxel_size == Approx(simulation_of(node).setup().cell_size));
    CHECK(file.voxel_zero.x == Approx(0.5 * simulation_of(node).setup().cell_size));
    // The kernel's faint tail stays out of the file: only cells of at least k_vdb_min_density.
    size_t liquid_cells = 0, faint_cells = 0;
    for (float rho : volume.density) {
      liquid_cells += rho >= liquid::k_vdb_min_density;
      faint_cells += rho > 0.0f && rho < liquid::k_vdb_min_density;
    }
    REQUIRE(liquid_cells > 100);
    REQUIRE(faint_cells > 0);  // else the threshold is not exercised
    CHECK(file.density.size() == liquid_cells);
    std::set<std::array<int, 3>> dense;
    for (const auto& v : file.density) {
      REQUIRE(v.index.z < volume.cells.z);  // 2D: one voxel deep
      REQUIRE(v.value == volume.density[volume.index(v.index.x, v.index.y, v.index.z)]);
      dense.insert({v.index.x, v.index.y, v.index.z});
    }
    for (const auto& v : file.velocity) {
      const glm::vec4 cell = volume.velocity[volume.index(v.index.x, v.index.y, v.index.z)];
      REQUIRE(cell.w >= 0.5f);
      REQUIRE(v.value == glm::vec3(cell));
      REQUIRE(dense.count({v.index.x, v.index.y, v.index.z}) == 1);  // no velocity without density
    }

    // The same frame written again gives the same bytes (OpenVDB's random UUID replaced).
    std::filesystem::path again = path;
    again += ".again.vdb";
    liquid::write_vdb(again, volume, liquid::VdbFrame{7, node.time(), node.scene().name});
    const auto bytes = [](const std::filesystem::path& p) {
      std::ifstream in(p, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    CHECK(bytes(path) == bytes(again));
    CHECK(liquid::read_vdb(again).density.size() == liquid_cells);
  }
  for (GridPath path : {GridPath::GeometryShader, GridPath::VertexLayer, GridPath::Atlas})
    REQUIRE_NO_VALIDATION_MESSAGES_ON(test::gpu_for(path));
}
#endif
