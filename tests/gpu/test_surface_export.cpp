// The liquid's surface as the capture tool exports it: a level set and a mesh of a pool at rest
// that hold the liquid's volume, close against the walls and floor, and lie on the density's
// isosurface the raymarch draws.
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/surface.h"
#include "liquid/node.h"
#include "liquid/scene.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/gpu/whitewater_helpers.h"
#include "tests/support/gpu.h"

#include <catch2/catch.hpp>
#include <glm/gtc/epsilon.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

namespace {

// A pool at rest over the whole floor: 10 cm of water on a 15 x 12 x 10 grid of 2 cm cells. The
// separable splat mirrors the kernel at the walls, so the density reaches rho0 at them; the point
// splat leaves the wall cells at 0.7 rho0 and the floor's edges below the iso level: its density
// integrates to 18 % less than the mass, and its surface (which follows the density) holds 9 % less.
const char* k_rest_pool_3d = R"({
  "name": "rest pool 3D", "dimension": 3, "domain": [0.3, 0.24, 0.2], "grid_resolution": 15,
  "particle_spacing": 0.01, "density": 1000, "stiffness": 9.8, "gamma": 5, "kernel_radius_cells": 3,
  "pic_ratio": 0.1, "pressure_force": "splat_adjoint", "splat": "separable", "time_step": 0.0004, "substeps": 50, "wall_margin_cells": 0.25,
  "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.3, 0.1, 0.2] } ] })";

// Divergence theorem over the triangles: the volume they enclose, positive when wound outward.
double enclosed_volume(const liquid::SurfaceMesh& mesh) {
  double six_volumes = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    six_volumes += glm::dot(a, glm::cross(b, c));
  }
  return six_volumes / 6.0;
}

struct EdgeCounts {
  size_t edges = 0, not_shared_by_two = 0, same_direction_twice = 0;
};
// Each edge of a closed, consistently wound mesh is shared by exactly two triangles, which run it
// in opposite directions.
EdgeCounts count_edges(const liquid::SurfaceMesh& mesh) {
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const glm::uvec3& t : mesh.triangles)
    for (const auto& [a, b] : {std::pair{t.x, t.y}, std::pair{t.y, t.z}, std::pair{t.z, t.x}}) ++directed[{a, b}];
  EdgeCounts counts;
  for (const auto& [edge, n] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    const int reverse = back == directed.end() ? 0 : back->second;
    if (edge.first < edge.second || reverse == 0) ++counts.edges;
    if (n + reverse != 2) ++counts.not_shared_by_two;
    if (n > 1) ++counts.same_direction_twice;
  }
  return counts;
}

}  // namespace

TEST_CASE("the exported surface of a pool at rest holds its volume and closes on the walls", "[gpu][liquid][export]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, liquid::parse_scene(k_rest_pool_3d, "rest_pool_3d.json"));
  const liquid::Diagnostics d = test::run_steps(node, 250);  // the lattice compresses under gravity
  const liquid::VolumeFrame volume = liquid::read_volume(context, node);
  const double liquid_volume = d.mass / double(node.scene().density);
  for (const int voxels_per_cell : {2, 1}) {
    const auto started = std::chrono::steady_clock::now();
    const liquid::LiquidSurface surface(volume, liquid::SurfaceSettings{.voxels_per_cell = voxels_per_cell});
    const liquid::SurfaceMesh mesh = surface.mesh(volume);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    const double enclosed = enclosed_volume(mesh);
    const EdgeCounts edges = count_edges(mesh);
    INFO(voxels_per_cell << " voxels a cell: " << mesh.triangles.size() << " triangles, enclosed " << enclosed
                  << " m^3 against mass / rho0 " << liquid_volume << " m^3 (" << 100.0 * (enclosed / liquid_volume - 1.0)
                  << " %), " << edges.edges << " edges, " << edges.not_shared_by_two << " not shared by two, "
                  << ms << " ms");
    REQUIRE(mesh.triangles.size() > 100);
    // At one voxel a cell the mesher's bevel along the box's edges, half a voxel wide, takes 6 %.
    if (voxels_per_cell == liquid::SurfaceSettings{}.voxels_per_cell) CHECK(std::abs(enclosed / liquid_volume - 1.0) < 0.03);
    CHECK(edges.not_shared_by_two == 0);
    CHECK(edges.same_direction_twice == 0);
    // Every vertex inside the domain (closed on the walls, not past them) and moving slowly.
    const glm::vec3 domain = node.scene().domain;
    const float tolerance = 1e-3f * float(surface.voxel_size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::vec3 p = mesh.positions[i];
      REQUIRE(glm::all(glm::greaterThanEqual(p, glm::vec3(-tolerance))));
      REQUIRE(glm::all(glm::lessThanEqual(p, domain + tolerance)));
      REQUIRE(glm::length(mesh.velocities[i]) < 0.1f);
    }

    // The level set's zero crossing on the density's isosurface: at each point between two
    // neighbouring cell centres where the trilinear density crosses the iso level (there it is
    // linear along the edge), the signed distance is within half a cell of zero.
    const float iso = liquid::SurfaceSettings{}.iso_level;
    const glm::ivec3 n = volume.cells;
    double worst = 0.0;
    int crossings = 0;
    for (int z = 0; z < n.z; ++z)
      for (int y = 0; y < n.y; ++y)
        for (int x = 0; x < n.x; ++x)
          for (const glm::ivec3 step : {glm::ivec3(1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, 0, 1)}) {
            const glm::ivec3 a(x, y, z), b = a + step;
            if (b.x >= n.x || b.y >= n.y || b.z >= n.z) continue;
            const float ra = volume.density[volume.index(a.x, a.y, a.z)], rb = volume.density[volume.index(b.x, b.y, b.z)];
            if ((ra - iso) * (rb - iso) >= 0.0f) continue;
            const float t = (ra - iso) / (ra - rb);
            const glm::vec3 at = volume.origin + (glm::vec3(a) + 0.5f + t * glm::vec3(step)) * volume.cell_size;
            worst = std::max(worst, double(std::abs(surface.signed_distance(at))));
            ++crossings;
          }
    INFO(crossings << " crossings, the largest distance " << worst / volume.cell_size << " cells");
    REQUIRE(crossings > 100);
    CHECK(worst < 0.5 * volume.cell_size);

    const std::filesystem::path path = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / "surface_rest_pool.vdb";
    std::filesystem::create_directories(path.parent_path());
    surface.write_vdb(path, liquid::VdbFrame{3, node.time(), node.scene().name});
    CHECK(std::filesystem::file_size(path) > 1000);
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// The dam break as it runs: the front, the impact on a box and the run-up on the far wall, in the
// shipped dam break's regime and cells (the whitewater tests' scene, without whitewater).
TEST_CASE("the exported surface of a running dam break holds its volume within 5 % and is closed", "[gpu][liquid][export]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::whitewater_dam_break(false));
  for (const int steps : {45, 45, 45, 75}) {  // 0.1, 0.2, 0.3 and 0.47 s
    const liquid::Diagnostics d = test::run_steps(node, steps);
    const liquid::VolumeFrame volume = liquid::read_volume(context, node);
    const liquid::LiquidSurface surface(volume, liquid::SurfaceSettings{});
    const liquid::SurfaceMesh mesh = surface.mesh(volume);
    const double liquid_volume = d.mass / double(node.scene().density);
    const double enclosed = enclosed_volume(mesh);
    const EdgeCounts edges = count_edges(mesh);
    INFO("t = " << node.time() << " s: " << mesh.triangles.size() << " triangles, enclosed " << enclosed
                << " m^3 against mass / rho0 " << liquid_volume << " m^3 (" << 100.0 * (enclosed / liquid_volume - 1.0)
                << " %), " << edges.not_shared_by_two << " of " << edges.edges << " edges not shared by two");
    REQUIRE(mesh.triangles.size() > 100);
    CHECK(std::abs(enclosed / liquid_volume - 1.0) < 0.05);
    CHECK(edges.not_shared_by_two == 0);
    CHECK(edges.same_direction_twice == 0);
  }
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("the surface of a domain full of liquid is its box and of an empty one nothing", "[gpu][liquid][export]") {
  liquid::VolumeFrame volume;
  volume.cells = {6, 5, 4};
  volume.cell_size = 0.1f;
  volume.origin = {1.0f, 2.0f, 3.0f};
  const size_t cells = 6 * 5 * 4;
  volume.density.assign(cells, 1.0f);
  volume.velocity.assign(cells, glm::vec4(0.5f, 0.0f, 0.0f, 1.0f));
  const liquid::LiquidSurface full(volume, {});
  const liquid::SurfaceMesh box = full.mesh(volume);
  const EdgeCounts edges = count_edges(box);
  CHECK(edges.not_shared_by_two == 0);
  CHECK(edges.same_direction_twice == 0);
  // The six walls' planes, the edges bevelled by the mesher (by about a voxel: 4 % of this small box).
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : box.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  CHECK(glm::all(glm::epsilonEqual(lo, volume.origin, 1e-4f)));
  CHECK(glm::all(glm::epsilonEqual(hi, volume.origin + glm::vec3(0.6f, 0.5f, 0.4f), 1e-4f)));
  INFO("enclosed " << enclosed_volume(box) << " m^3");
  CHECK(enclosed_volume(box) < 0.6 * 0.5 * 0.4);
  CHECK(enclosed_volume(box) > 0.95 * 0.6 * 0.5 * 0.4);
  CHECK(full.signed_distance({1.3f, 2.25f, 3.2f}) == Approx(-0.15f).margin(0.01f));  // band's end: 3 voxels
  CHECK(full.signed_distance({1.01f, 2.25f, 3.2f}) == Approx(-0.01f).margin(0.002f));
  for (const glm::vec3& v : box.velocities) REQUIRE(v == glm::vec3(0.5f, 0.0f, 0.0f));

  volume.density.assign(cells, 0.0f);
  const liquid::LiquidSurface empty(volume, {});
  CHECK(empty.mesh(volume).triangles.empty());
  CHECK(empty.signed_distance({1.3f, 2.25f, 3.2f}) == Approx(0.15f));
}

TEST_CASE("the surface refuses a 2D volume and settings out of range", "[gpu][liquid][export]") {
  liquid::VolumeFrame volume;
  volume.cells = {4, 4, 4};
  volume.cell_size = 0.1f;
  volume.density.assign(64, 1.0f);
  volume.velocity.assign(64, glm::vec4(0.0f));
  CHECK_THROWS_WITH(liquid::LiquidSurface(volume, {.voxels_per_cell = 0}), Catch::Contains("voxels a cell"));
  CHECK_THROWS_WITH(liquid::LiquidSurface(volume, {.voxels_per_cell = 9}), Catch::Contains("voxels a cell"));
  CHECK_THROWS_WITH(liquid::LiquidSurface(volume, {.adaptivity = NAN}), Catch::Contains("adaptivity"));
  CHECK_THROWS_WITH(liquid::LiquidSurface(volume, {.adaptivity = 1.5f}), Catch::Contains("adaptivity"));
  volume.cells = {8, 8, 1};
  CHECK_THROWS_WITH(liquid::LiquidSurface(volume, {}), Catch::Contains("3D"));
}
#endif
