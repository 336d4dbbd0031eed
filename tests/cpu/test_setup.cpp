// Derived setup with no GPU: grid sizing (section 7's N^(1/d) rule), the deterministic particle
// lattice, kernel normalisation and rest density, emitters, device limits, and the physical
// sanity of every shipped scene.
#include "liquid/physics/setup.h"
#include "liquid/physics/time_step.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace liquid;
using Catch::Contains;
using Catch::StartsWith;
using namespace test_scenes;

namespace {

constexpr double k_pi = 3.14159265358979323846;

// A liquid scene with one block, built in code.
Scene block_scene(int dimension, glm::vec3 domain, FluidBlock block, float spacing) {
  Scene scene;
  scene.name = "test";
  scene.dimension = dimension;
  scene.domain = domain;
  scene.particle_spacing = spacing;
  scene.fluid_blocks = {block};
  return scene;
}

// Composite Simpson rule of f over [a, b] with n (even) intervals.
template <typename F>
double simpson(F f, double a, double b, int n) {
  const double step = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * step) * (i % 2 ? 4.0 : 2.0);
  return sum * step / 3.0;
}

}  // namespace

TEST_CASE("kernel integral matches a numeric quadrature", "[setup]") {
  for (double r : {1.0, 2.0, 3.0, 4.5, 8.0}) {
    INFO("r = " << r);
    const auto w = [r](double d) { return std::pow(1.0 - d * d / (r * r), 3.0); };
    const double area = simpson([&](double d) { return w(d) * 2.0 * k_pi * d; }, 0.0, r, 2000);
    const double volume = simpson([&](double d) { return w(d) * 4.0 * k_pi * d * d; }, 0.0, r, 2000);
    CHECK(kernel_integral_cells(2, r) == Approx(area).epsilon(1e-9));
    CHECK(kernel_integral_cells(3, r) == Approx(volume).epsilon(1e-9));
  }
  // And against a plain 2D Riemann sum over cells of a fine grid (no radial symmetry assumed).
  const double r = 3.0, step = 0.01;
  double sum = 0.0;
  for (double x = -r + step / 2; x < r; x += step)
    for (double y = -r + step / 2; y < r; y += step) {
      const double q = 1.0 - (x * x + y * y) / (r * r);
      if (q > 0.0) sum += q * q * q * step * step;
    }
  CHECK(kernel_integral_cells(2, r) == Approx(sum).epsilon(1e-4));
  CHECK_THROWS(kernel_integral_cells(1, 3.0));
}

TEST_CASE("dam_break_2d gives the expected particles and grid", "[setup]") {
  const Scene scene = scene_of("dam_break_2d.json");
  const SimulationSetup setup = make_setup(scene, {});
  // 0.3 / 0.0029 = 103.4 and 0.45 / 0.0029 = 155.2 spacings.
  CHECK(setup.initial_particles == 103 * 155);
  CHECK(setup.capacity == setup.initial_particles);
  CHECK(setup.positions.size() == size_t(setup.initial_particles));
  CHECK(setup.velocities.size() == size_t(setup.initial_particles));
  // No grid_resolution: round(sqrt(15965)) = 126 cells along x; y gets round(0.6 * 126) = 76.
  CHECK(setup.grid_cells == glm::ivec3(126, 76, 1));
  CHECK(setup.cell_size == Approx(1.0 / 126.0));
  CHECK(setup.domain.x == Approx(1.0f));
  CHECK(setup.domain.y == Approx(76.0 / 126.0));
  CHECK(setup.particle_texture == glm::ivec2(128, 125));
  CHECK(setup.particle_mass == Approx(1000.0 * 0.0029 * 0.0029));
  // The shipped scene uses the separable splat: its kernel's integral, (sum of the taps)^2.
  REQUIRE(setup.splat == SplatMode::Separable);
  CHECK(setup.density_scale ==
        Approx(setup.particle_mass / (std::pow(setup.cell_size, 2) * splat_kernel_integral_cells(SplatMode::Separable, 2, 3.0))));
  CHECK(setup.stiffness == scene.stiffness);
  CHECK(setup.gamma == scene.gamma);
  CHECK(setup.gravity == glm::vec3(0.0f, -9.81f, 0.0f));

  // Half a spacing from the walls; the shipped scene runs the pressure projection, whose liquid
  // is incompressible, so the column starts on the uniform lattice (see the hydrostatic start test).
  REQUIRE(scene.projection_iterations > 0);
  CHECK(setup.positions.front().x == Approx(0.00145f));
  CHECK(setup.positions.front().y == Approx(0.00145f));
  for (size_t i = 0; i < setup.positions.size(); ++i) {
    const glm::vec4 p = setup.positions[i];
    INFO("particle " << i);
    REQUIRE((p.x > 0.0f && p.x < 0.3f && p.y > 0.0f && p.y < 0.45f));
    REQUIRE(p.z == 0.0f);
    REQUIRE(p.w == 1.0f);
    REQUIRE(setup.velocities[i] == glm::vec4(0.0f));
  }
}

TEST_CASE("the default grid follows the particle spacing, two spacings a cell, at least 8 cells", "[setup]") {
  // 3D: a 0.2 m cube at 1 cm in a 1 x 0.5 x 0.25 m box: 2 cm cells, whatever the particle count.
  Scene cube = block_scene(3, {1.0f, 0.5f, 0.25f}, {{0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, 0.2f}, {}}, 0.01f);
  SimulationSetup setup = make_setup(cube, {});
  REQUIRE(setup.capacity == 8000);
  CHECK(setup.grid_cells == glm::ivec3(50, 25, 13));  // 12.5 rounds to 13, the box snapped to it
  CHECK(setup.cell_size == Approx(0.02f));
  CHECK(setup.particle_spacing / setup.cell_size == Approx(1.0 / k_default_spacings_per_cell));

  // The case N^(1/d) got wrong: a 0.1 x 0.2 m column at 1.5 mm in a 0.8 x 0.3 m tank. From the
  // particle count it had 94 cells, 5.7 spacings a cell; from the spacing, 267 cells of 3 mm.
  Scene column = block_scene(2, {0.8f, 0.3f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.1f, 0.2f, 0.0f}, {}}, 0.0015f);
  setup = make_setup(column, {});
  CHECK(setup.grid_cells == glm::ivec3(267, 100, 1));
  CHECK(setup.cell_size == Approx(0.8 / 267));

  // Coarse particles in a small box: clamped to 8 cells.
  Scene few = block_scene(2, {0.1f, 0.1f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.05f, 0.05f, 0.0f}, {}}, 0.01f);
  CHECK(make_setup(few, {}).grid_cells == glm::ivec3(8, 8, 1));

  // An emitter's capacity does not change the cells: the spacing sets them.
  few.emitters = {Emitter{{0.05f, 0.05f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.01f, 0.0f, 1e30f, 10000}};
  CHECK(make_setup(few, {}).grid_cells == glm::ivec3(8, 8, 1));

  // A scene's grid_resolution wins; shorter axes are rounded to whole cells and the box snapped.
  few.emitters.clear();
  few.domain = {1.0f, 0.337f, 0.0f};
  few.grid_resolution = 10;
  setup = make_setup(few, {});
  CHECK(setup.grid_cells == glm::ivec3(10, 3, 1));
  CHECK(setup.domain.y == Approx(0.3f));

  // A default grid past the device's limits is refused naming where it came from.
  Scene fine = block_scene(2, {10.0f, 1.0f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.01f, 0.01f, 0.0f}, {}}, 0.0002f);
  CHECK_THROWS_WITH(make_setup(fine, {}),
                    Catch::Contains("grid 25000 x 2500 x 1 exceeds the device limit of 16384 texels per axis") &&
                        Catch::Contains("(the default: 2 particle spacings a cell; set grid_resolution)"));
}

TEST_CASE("a scene without time_step gets its regime's step at its own cell size", "[setup][time_step]") {
  // Only the required keys: the projection, in the long-step regime, k = 50, gamma = 5, 2 cm
  // cells: an acoustic CFL of 1.3 at the speed of sound at rest, sqrt(250) m/s.
  Scene scene = block_scene(2, {1.0f, 0.6f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.3f, 0.4f, 0.0f}, {}}, 0.01f);
  REQUIRE(scene.time_step == 0.0f);
  SimulationSetup setup = make_setup(scene, {});
  CHECK(setup.time_step == Approx(k_acoustic_cfl_smoothed * 0.02 / std::sqrt(250.0)));
  CHECK(scene_time_step(scene) == Approx(setup.time_step));
  CHECK(setup.time_step < largest_stable_time_step(setup));

  // The chapter's pressure: its regime's CFL of 0.16.
  scene.pressure_force = PressureForce::Chapter;
  scene.projection_iterations = 0;
  setup = make_setup(scene, {});
  CHECK(setup.time_step == Approx(k_acoustic_cfl_chapter * 0.02 / std::sqrt(250.0)));
  CHECK(setup.time_step < largest_stable_time_step(setup));

  // The long-step regime without the projection: its CFL, scaled by the kernel radius over 3 cells.
  scene.pressure_force = PressureForce::SplatAdjoint;
  scene.pic_ratio_reference_step = 1e-4f;
  scene.kernel_radius_cells = 4.0f;
  setup = make_setup(scene, {});
  CHECK(setup.time_step == Approx(k_acoustic_cfl_smoothed * 4.0 / 3.0 * setup.cell_size / std::sqrt(250.0)));

  // Shallow water: the wave speed sqrt(|g| rest_depth).
  Scene shallow = scene_of("shallow_water.json");
  shallow.time_step = 0.0f;
  setup = make_setup(shallow, {});
  CHECK(setup.time_step == Approx(k_acoustic_cfl_chapter * setup.cell_size / std::sqrt(9.81 * 0.05)));

  // Every shipped scene's own step is within its regime's stable one.
  for (const std::filesystem::path& path : shipped_scenes()) {
    INFO(path);
    const SimulationSetup shipped = make_setup(load_scene(path), {});
    CHECK(shipped.time_step <= largest_stable_time_step(shipped));
  }
}

TEST_CASE("a fixed time_step past its regime's stable step is refused before the run", "[setup][time_step]") {
  // The old default of 2 ms on the scene above under the chapter's pressure: an acoustic CFL of
  // 1.6, past the chapter's 1.
  Scene scene = block_scene(2, {1.0f, 0.6f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.3f, 0.4f, 0.0f}, {}}, 0.01f);
  scene.pressure_force = PressureForce::Chapter;
  scene.projection_iterations = 0;
  scene.source = "scene.json";
  scene.time_step = 0.002f;
  CHECK_THROWS_WITH(make_setup(scene, {}),
                    Catch::StartsWith("scene.json: time_step: 0.002 s is past the longest stable step of this scene, ") &&
                        Catch::Contains("in the chapter's regime on cells of 0.02 m") &&
                        Catch::EndsWith("lower it, leave it out for the regime's step, or add adaptive_time_step"));
  // Just within it: accepted; adaptive steps adapt, so their largest step is not refused.
  scene.time_step = float(0.99 * k_max_acoustic_cfl_chapter * 0.02 / (std::sqrt(250.0) + std::sqrt(2 * 9.81)));
  CHECK_NOTHROW(make_setup(scene, {}));
  scene.time_step = 0.002f;
  scene.adaptive_time_step = AdaptiveTimeStep{};
  CHECK_NOTHROW(make_setup(scene, {}));
}

TEST_CASE("the lattice of symmetric_2d is mirror-symmetric", "[setup]") {
  const SimulationSetup setup = setup_of("symmetric_2d.json");
  const float length = setup.domain.x;
  REQUIRE(length == scene_of("symmetric_2d.json").domain.x);
  // The scene's numbers are dyadic, so mirroring is exact in float.
  std::set<std::pair<float, float>> points;
  for (const glm::vec4& p : setup.positions) points.insert({p.x, p.y});
  REQUIRE(points.size() == setup.positions.size());
  for (const glm::vec4& p : setup.positions) REQUIRE(points.count({length - p.x, p.y}) == 1);
}

TEST_CASE("mirrored blocks give mirrored particles", "[setup]") {
  // Blocks 30 spacings wide (the lattice starts at min + s/2, so it mirrors when the extent is a
  // whole number of spacings), with decimal bounds that are not exact in binary.
  Scene scene = block_scene(2, {1.0f, 0.6f, 0.0f}, {{0.1f, 0.05f, 0.0f}, {0.31f, 0.3f, 0.0f}, {}}, 0.007f);
  scene.fluid_blocks.push_back({{0.69f, 0.05f, 0.0f}, {0.9f, 0.3f, 0.0f}, {}});
  const SimulationSetup setup = make_setup(scene, {});
  REQUIRE(setup.initial_particles % 2 == 0);
  const size_t half = setup.positions.size() / 2;
  std::vector<std::pair<float, float>> left, mirrored;
  for (size_t i = 0; i < half; ++i) left.push_back({setup.positions[i].x, setup.positions[i].y});
  for (size_t i = half; i < setup.positions.size(); ++i)
    mirrored.push_back({1.0f - setup.positions[i].x, setup.positions[i].y});
  std::sort(left.begin(), left.end());
  std::sort(mirrored.begin(), mirrored.end());
  for (size_t i = 0; i < half; ++i) {
    REQUIRE(left[i].first == Approx(mirrored[i].first).margin(1e-6));
    REQUIRE(left[i].second == mirrored[i].second);
  }
}

TEST_CASE("the setup is deterministic", "[setup]") {
  const SimulationSetup a = setup_of("obstacles_2d.json");
  const SimulationSetup b = setup_of("obstacles_2d.json");
  CHECK(a.positions == b.positions);
  CHECK(a.velocities == b.velocities);
}

TEST_CASE("auto rest density is within 5% of the liquid's density", "[setup]") {
  for (const auto& path : shipped_scenes()) {
    INFO(path.filename().string());
    const Scene scene = load_scene(path);
    if (scene.rest_density) continue;
    CHECK(make_setup(scene, {}).rest_density == Approx(scene.density).epsilon(0.05));
  }
  // Also at spacings from a quarter cell to one and a half cells, in 2D and 3D.
  for (int d : {2, 3})
    for (float spacing_cells : {0.25f, 0.5f, 0.75f, 1.0f, 1.5f}) {
      INFO("dimension " << d << ", spacing " << spacing_cells << " cells");
      const float h = 0.02f;
      Scene scene = block_scene(d, {1.0f, 1.0f, d == 3 ? 1.0f : 0.0f},
                                {{0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, d == 3 ? 0.2f : 0.0f}, {}}, spacing_cells * h);
      scene.grid_resolution = 50;
      scene.density = 800.0f;
      CHECK(make_setup(scene, {}).rest_density == Approx(800.0f).epsilon(0.05));
    }
}

TEST_CASE("a given rest density is kept", "[setup]") {
  Scene scene = load_scene(k_scene_dir / "rest_pool_2d.json");
  scene.rest_density = 1234.0f;
  CHECK(make_setup(scene, {}).rest_density == 1234.0f);
}

TEST_CASE("shallow water derives P = g h", "[setup]") {
  const Scene scene = scene_of("shallow_water.json");
  const SimulationSetup setup = make_setup(scene, {});
  CHECK(setup.shallow_water);
  CHECK(setup.rest_depth == scene.rest_depth);
  CHECK(setup.gamma == 1.0f);
  CHECK(setup.stiffness == Approx(glm::length(scene.gravity) * scene.rest_depth));
  CHECK(setup.gravity == glm::vec3(0.0f));
  CHECK(setup.rest_density == Approx(scene.density).epsilon(0.05));
  CHECK(setup.grid_cells == glm::ivec3(256, 256, 1));
}

TEST_CASE("emitters add particles monotonically up to their capacity", "[setup]") {
  const Scene scene = load_scene(k_scene_dir / "jet_2d.json");
  REQUIRE(scene.emitters.size() == 1);
  const Emitter& jet = scene.emitters[0];
  const double rate = emitter_rate(jet, 2, scene.particle_spacing);
  CHECK(rate == Approx(2.0 * jet.radius * glm::length(jet.velocity) / std::pow(scene.particle_spacing, 2)));
  int previous = 0;
  for (double t = 0.0; t <= 20.0; t += 0.01) {
    const int n = emitted_by(jet, 2, scene.particle_spacing, t);
    REQUIRE(n >= previous);
    REQUIRE(n <= jet.capacity);
    previous = n;
  }
  CHECK(previous == jet.capacity);
  CHECK(emitted_by(jet, 2, scene.particle_spacing, 0.0) == 0);
  CHECK(emitted_by(jet, 2, scene.particle_spacing, 1.0) == int(std::floor(rate)));

  // A start and stop time: nothing before the start, no growth after the stop.
  Emitter timed = jet;
  timed.start_time = 1.0f;
  timed.stop_time = 1.5f;
  timed.capacity = 1 << 20;
  CHECK(emitted_by(timed, 2, scene.particle_spacing, 0.5) == 0);
  CHECK(emitted_by(timed, 2, scene.particle_spacing, 1.25) == int(std::floor(rate * 0.25)));
  CHECK(emitted_by(timed, 2, scene.particle_spacing, 1.5) == emitted_by(timed, 2, scene.particle_spacing, 100.0));

  // 3D flux through a disc.
  const Emitter nozzle{{0.5f, 0.5f, 0.5f}, {0.0f, -2.0f, 0.0f}, 0.03f, 0.0f, 1e30f, 1000};
  CHECK(emitter_rate(nozzle, 3, 0.01f) == Approx(k_pi * 0.03 * 0.03 * 2.0 / 1e-6).epsilon(1e-5));
}

TEST_CASE("particle texture is the smallest power-of-two width that fits", "[setup]") {
  for (const auto& path : shipped_scenes()) {
    INFO(path.filename().string());
    const SimulationSetup setup = make_setup(load_scene(path), {});
    const glm::ivec2 t = setup.particle_texture;
    const int side = int(std::ceil(std::sqrt(double(setup.capacity))));
    CHECK((t.x & (t.x - 1)) == 0);
    CHECK(t.x >= side);
    CHECK(t.x / 2 < side);
    CHECK(std::int64_t(t.x) * t.y >= setup.capacity);
    CHECK(std::int64_t(t.x) * (t.y - 1) < setup.capacity);
  }
}

TEST_CASE("scenes past the device limits are rejected naming the limit", "[setup]") {
  DeviceLimits small_2d;
  small_2d.max_image_dimension_2d = 100;
  // dam_break_2d: 15965 particles need a 128-wide particle texture.
  REQUIRE_THROWS_WITH(setup_of("dam_break_2d.json", small_2d),
                      Contains("dam_break_2d.json: fluid_blocks: capacity of 15965 particles") &&
                          Contains("max_image_dimension_2d") &&
                          Contains("100"));
  small_2d.max_image_dimension_2d = 128;
  Scene wide = load_scene(k_scene_dir / "rest_pool_2d.json");
  wide.grid_resolution = 200;
  REQUIRE_THROWS_WITH(make_setup(wide, small_2d),
                      Contains("grid 200 x 200 x 1 exceeds the device limit of 128 texels per axis") &&
                          Contains("max_image_dimension_2d"));

  DeviceLimits small_3d;
  small_3d.max_image_dimension_3d = 48;
  REQUIRE_THROWS_WITH(setup_of("dam_break_3d.json", small_3d),
                      Contains("dam_break_3d.json: grid_resolution: grid 64 x 38 x 32 exceeds the device limit") &&
                          Contains("of 48") &&
                          Contains("max_image_dimension_3d"));
  small_3d = {};
  small_3d.max_framebuffer_layers = 16;
  REQUIRE_THROWS_WITH(setup_of("dam_break_3d.json", small_3d),
                      Contains("32 framebuffer layers") && Contains("16 (max_framebuffer_layers)"));
  CHECK_NOTHROW(setup_of("dam_break_3d.json", {2048, 64, 32}));
}

TEST_CASE("errors found by the setup name the scene's file and the field", "[setup]") {
  const auto scene_file = [](const std::string& text) { return parse_scene(text, "scenes/x.json"); };
  // A sphere that covers the whole block: nothing is left to simulate.
  const Scene covered = scene_file(R"({"name": "Covered", "dimension": 2, "domain": [1, 1],
      "particle_spacing": 0.01, "fluid_blocks": [{"min": [0.4, 0.4], "max": [0.6, 0.6]}],
      "obstacles": [{"shape": "sphere", "center": [0.5, 0.5], "radius": 0.3}]})");
  REQUIRE_THROWS_WITH(make_setup(covered, {}), StartsWith("scenes/x.json: obstacles: cover every particle"));
  // 4000 x 4000 x 4000 particles: past the CPU guard, refused before any is made.
  const Scene huge = scene_file(R"({"name": "Huge", "dimension": 3, "domain": [1, 1, 1],
      "particle_spacing": 0.00025, "grid_resolution": 2048, "fluid_blocks": [{"min": [0, 0, 0], "max": [1, 1, 1]}]})");
  REQUIRE_THROWS_WITH(make_setup(huge, {}), StartsWith("scenes/x.json: fluid_blocks: hold ") &&
                                               Contains("particles, more than the supported 67108864"));
  // A scene built in code has no file: its name stands in.
  Scene coded = covered;
  coded.source.clear();
  REQUIRE_THROWS_WITH(make_setup(coded, {}), StartsWith("Covered: obstacles: "));
}

TEST_CASE("fluid blocks that cannot be filled are rejected", "[setup]") {
  Scene scene = block_scene(2, {1.0f, 0.6f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.3f, 0.3f, 0.0f}, {}}, 0.01f);
  scene.fluid_blocks.push_back({{0.5f, 0.0f, 0.0f}, {0.505f, 0.3f, 0.0f}, {}});
  REQUIRE_THROWS_WITH(make_setup(scene, {}), Contains("test: fluid_blocks[1]: produces no particle"));

  // y = 0.603 m snaps down to 6 cells of 0.1 m; the block's top row lands above 0.6 m.
  Scene tall = block_scene(2, {1.0f, 0.603f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.5f, 0.603f, 0.0f}, {}}, 0.003f);
  tall.grid_resolution = 10;
  REQUIRE_THROWS_WITH(make_setup(tall, {}), Contains("test: fluid_blocks[0]") && Contains("snapped to whole cells"));

  // Particles farther apart than the kernel radius would never interact.
  Scene sparse = block_scene(2, {1.0f, 1.0f, 0.0f}, {{0.0f, 0.0f, 0.0f}, {0.5f, 0.5f, 0.0f}, {}}, 0.05f);
  sparse.grid_resolution = 256;
  REQUIRE_THROWS_WITH(make_setup(sparse, {}), Contains("test: particle_spacing") && Contains("kernel radius"));
}

TEST_CASE("ground height sums the Gaussian hills", "[setup]") {
  Scene scene;
  scene.ground = {{{0.3f, 0.4f}, 0.05f, 0.1f}, {{0.8f, 0.8f}, -0.02f, 0.05f}};
  CHECK(ground_height(scene, {0.3f, 0.4f}) == Approx(0.05 + -0.02 * std::exp(-(0.25 + 0.16) / (2 * 0.0025))));
  CHECK(ground_height(scene, {0.4f, 0.4f}) == Approx(0.05 * std::exp(-0.5)).epsilon(1e-4));
  CHECK(ground_height(scene, {0.8f, 0.8f}) == Approx(-0.02 + 0.05 * std::exp(-(0.25 + 0.16) / 0.02)));
  CHECK(ground_height(Scene{}, {0.5f, 0.5f}) == 0.0f);
}

TEST_CASE("shipped scenes have the particle counts and grids they promise", "[setup]") {
  const auto count_near = [](const char* file, int expected) {
    INFO(file);
    const SimulationSetup setup = setup_of(file);
    CHECK(std::abs(setup.capacity - expected) <= expected / 50);
    return setup;
  };
  CHECK(count_near("paper_2d_16k.json", 16000).grid_cells == glm::ivec3(256, 256, 1));
  CHECK(count_near("paper_2d_32k.json", 32000).grid_cells == glm::ivec3(256, 256, 1));
  CHECK(count_near("paper_2d_64k.json", 64000).grid_cells == glm::ivec3(256, 256, 1));
  CHECK(count_near("paper_3d.json", 125000).grid_cells.x == 96);
  CHECK(count_near("shallow_water.json", 42000).grid_cells == glm::ivec3(256, 256, 1));
  CHECK(count_near("dam_break_3d.json", 60000).grid_cells.x == 64);
  CHECK(count_near("dam_break_2d.json", 16000).initial_particles > 0);
  CHECK(count_near("rest_pool_2d.json", 4096).grid_cells == glm::ivec3(64, 64, 1));
  CHECK(count_near("symmetric_2d.json", 4096).grid_cells == glm::ivec3(64, 64, 1));
  CHECK(count_near("small_3d.json", 8300).grid_cells.x == 24);
  CHECK(count_near("obstacles_2d.json", 8160).grid_cells.x == 128);
  CHECK(count_near("jet_2d.json", 6000).initial_particles == 0);
}

TEST_CASE("shipped scenes start every particle inside the domain", "[setup]") {
  // The solver keeps particles `wall_margin_cells` inside the walls, but one that starts closer
  // (the lattice's first layer, half a spacing out) is only kept from moving further out.
  for (const auto& path : shipped_scenes()) {
    INFO(path.filename().string());
    const Scene scene = load_scene(path);
    const SimulationSetup setup = make_setup(scene, {});
    CHECK(setup.wall_margin == scene.wall_margin_cells * setup.cell_size);
    for (const glm::vec4& p : setup.positions)
      for (int a = 0; a < setup.dimension; ++a) {
        INFO("axis " << a << " at " << p[a]);
        REQUIRE(p[a] > 0.0f);
        REQUIRE(p[a] < setup.domain[a]);
      }
  }
}

TEST_CASE("a block resting on the floor starts hydrostatically compressed", "[setup]") {
  // Under the splat-adjoint pressure still water holds its weight with P = |g| d at depth d, so
  // its density is rho0 (1 + |g| d / k)^(1 / gamma): the layers of a block on the floor are packed
  // by that factor, the top layer least. A floating block (free fall) and the chapter's mode start
  // on the uniform lattice, as does the pressure projection's incompressible liquid.
  Scene scene = scene_of("rest_pool_2d.json");
  scene.projection_iterations = 0;  // the equation of state's pool
  const double s = scene.particle_spacing, g = 9.81, k = scene.stiffness, gamma = scene.gamma;
  auto layer_heights = [](const SimulationSetup& setup) {
    std::set<float> heights;
    for (const glm::vec4& p : setup.positions) heights.insert(p.y);
    return std::vector<float>(heights.begin(), heights.end());
  };
  const std::vector<float> layers = layer_heights(make_setup(scene, {}));
  const double top = (double(layers.size()) - 0.5) * s;  // the uncompressed top layer
  REQUIRE(layers.size() > 20);
  for (size_t j = 1; j + 1 < layers.size(); ++j) {
    const double gap = (double(layers[j + 1]) - double(layers[j - 1])) / 2.0;
    const double depth = layers.back() - double(layers[j]) + 0.5 * s;
    INFO("layer " << j << " at " << layers[j] << " m, depth " << depth << " m");
    CHECK(gap == Approx(s / std::pow(1.0 + g * depth / k, 1.0 / gamma)).epsilon(2e-3));
  }
  CHECK(layers.front() < 0.5 * s);
  CHECK(layers.front() > 0.45 * s);
  CHECK(layers.back() < top);

  for (const char* start : {"floating", "chapter", "projection"}) {
    Scene uniform = scene;
    const bool floating = start == std::string("floating");
    if (floating) {
      uniform.fluid_blocks[0].min.y += 0.1f;
      uniform.fluid_blocks[0].max.y += 0.1f;
    } else if (start == std::string("chapter")) {
      uniform.pressure_force = PressureForce::Chapter;
      uniform.time_step = 0.0f;  // the chapter's regime's own step (the long step would be refused)
    } else {
      uniform.projection_iterations = 4;
    }
    INFO(start);
    const std::vector<float> uniform_layers = layer_heights(make_setup(uniform, {}));
    REQUIRE(uniform_layers.size() == layers.size());
    const double bottom = floating ? 0.1 : 0.0;
    for (size_t j = 0; j < uniform_layers.size(); ++j)
      CHECK(uniform_layers[j] == Approx(bottom + (j + 0.5) * s).margin(1e-6));
  }
}

TEST_CASE("shipped scenes are in the stable weakly compressible regime", "[setup]") {
  for (const auto& path : shipped_scenes()) {
    INFO(path.filename().string());
    const Scene scene = load_scene(path);
    const SimulationSetup setup = make_setup(scene, {});
    const double g = glm::length(scene.gravity);
    double sound = std::sqrt(double(setup.stiffness) * setup.gamma);
    if (scene.mode == SimulationMode::ShallowWater) {
      // Waves travel at sqrt(g depth); the raised water of the shipped scene doubles the depth.
      sound *= std::sqrt(2.0);
    } else {
      // Fastest expected flow: the initial or jet speed plus a free fall from the highest liquid.
      double top = 0.0, speed = 0.0;
      for (const FluidBlock& b : scene.fluid_blocks) {
        top = std::max(top, double(b.max.y));
        speed = std::max(speed, double(glm::length(b.velocity)));
      }
      for (const Emitter& e : scene.emitters) {
        top = std::max(top, double(e.position.y));
        speed = std::max(speed, double(glm::length(e.velocity)));
      }
      const double fastest = std::sqrt(speed * speed + 2.0 * g * top);
      // Mach number at most 0.45: density varies by a few percent in the fastest flow.
      CHECK(sound >= 2.2 * fastest);
    }
    // The acoustic CFL of the scene's regime (liquid/physics/time_step.h): the chapter's 0.16, or the
    // longer steps of the splat-adjoint pressure with the PIC blend per second, whose reference
    // step is one of the chapter's regime (where r = 0.05 was chosen).
    const double acoustic_step = setup.cell_size / sound;
    CHECK(scene.time_step <= regime_acoustic_cfl(setup) * acoustic_step);
    if (setup.long_steps && setup.pic_ratio_reference_step > 0.0f) {  // the projection needs none
      CHECK(setup.pic_ratio_reference_step <= k_acoustic_cfl_chapter * acoustic_step * 1.001);
      // and r was chosen at a step of the chapter's regime, not far below it (r(dt) would near PIC).
      CHECK(scene.time_step <= 8.2 * setup.pic_ratio_reference_step);
    }
    // A rendered frame covers about 1/30 s of simulated time.
    CHECK(scene.time_step * scene.substeps == Approx(1.0 / 30.0).epsilon(0.05));
  }
}

TEST_CASE("fluid blocks are carved around the obstacles they overlap", "[setup]") {
  const Scene scene = parse_scene(R"({
    "name": "carved", "dimension": 2, "domain": [1.0, 0.5], "grid_resolution": 64, "pressure_force": "chapter",
    "particle_spacing": 0.01, "fluid_blocks": [ { "min": [0.0, 0.0], "max": [1.0, 0.2] } ],
    "obstacles": [ { "shape": "sphere", "center": [0.5, 0.1], "radius": 0.08 } ] })",
                                  "carved.json");
  const SimulationSetup setup = make_setup(scene, {});
  // Lattice points are left out up to three quarters of the obstacle's band (one kernel radius,
  // 3 cells of 1/64 m) outside the surface, where its artificial density would blast them away.
  CHECK(setup.obstacle_band == Approx(3.0 / 64.0));
  const float carved_to = 0.08f + 0.75f * setup.obstacle_band;
  int outside = 0;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 100; ++i)
      if (glm::length(glm::vec2(0.005f + 0.01f * i, 0.005f + 0.01f * j) - glm::vec2(0.5f, 0.1f)) >= carved_to) ++outside;
  CHECK(2000 - outside > 350);  // a fifth of the block (carving to half a spacing left out 227)
  CHECK(setup.initial_particles == outside);
  CHECK(setup.initial_particles == int(setup.positions.size()));
  CHECK(setup.capacity == setup.initial_particles);
  for (const glm::vec4& p : setup.positions)
    REQUIRE(glm::length(glm::vec2(p) - glm::vec2(0.5f, 0.1f)) >= carved_to - 1e-5f);
}

TEST_CASE("dam_break_tank_2d is SPlisHSPlasH's DamBreakModel_2D at 64,516 particles", "[setup]") {
  // tools/dfsph/compare_dfsph.py runs the two side by side: DFSPH with particle radius 0.0029412 fills its
  // 1.5 m column, 2.5 cm off the floor and the left wall of a 4 m tank, with 254 x 254 particles.
  const Scene scene = scene_of("dam_break_tank_2d.json");
  const SimulationSetup setup = make_setup(scene, {});
  CHECK(setup.initial_particles == 254 * 254);
  CHECK(scene.domain.x == 4.0f);
  CHECK(scene.domain.y == 4.0f);
  REQUIRE(scene.fluid_blocks.size() == 1);
  CHECK(scene.fluid_blocks[0].min == glm::vec3(0.025f, 0.025f, 0.0f));
  CHECK(scene.fluid_blocks[0].max.x == Approx(1.525f));
  CHECK(scene.fluid_blocks[0].max.y == Approx(1.525f));
  CHECK(scene.particle_spacing == Approx(2.0 * 0.0029412));
}

TEST_CASE("a scene built in code is held to the projection's needs as a file is", "[setup]") {
  Scene scene = scene_of("rest_pool_2d.json");
  REQUIRE(scene.projection_iterations > 0);
  scene.pressure_force = PressureForce::Chapter;
  scene.time_step = 0.0f;
  REQUIRE_THROWS_WITH(make_setup(scene, {}),
                      Catch::Contains("rest_pool_2d.json: projection_iterations: needs \"pressure_force\": \"splat_adjoint\""));
  scene.pressure_force = PressureForce::SplatAdjoint;
  scene.projection_iterations = 1;
  REQUIRE_THROWS_WITH(make_setup(scene, {}), Catch::Contains("projection_iterations: must be 0 (no projection) or at least 2"));
}
