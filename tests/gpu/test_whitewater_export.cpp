// The whitewater's caches on the device, as liquid_capture writes them: the PLY of the secondary
// particles a run reads back, and the foam's grid beside the density in the OpenVDB file, each
// checked by reading the file back (tests/support/ply_points.h; OpenVDB itself).
#include "liquid/export/volume.h"
#include "liquid/export/whitewater_ply.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/gpu/whitewater_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/ply_points.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/vdb.h"
#endif

#include <catch2/catch.hpp>

#include <array>
#include <filesystem>
#include <set>

namespace {

// Steps of the small dam break (0.27 s) after which it holds all three kinds: about 3,000 particles,
// a few dozen of them spray.
constexpr int k_steps = 120;

}  // namespace

TEST_CASE("a run's whitewater PLY holds every secondary particle read back, and its VDB a foam grid of their count",
          "[gpu][whitewater][export]") {
  liquid::LiquidNode node(test::gpu(), test::whitewater_dam_break());
  test::run_steps(node, k_steps);
  const std::vector<liquid::WhitewaterParticle> live = simulation_of(node).read_whitewater();
  std::array<int, 4> kinds{};
  for (const liquid::WhitewaterParticle& p : live) ++kinds[size_t(p.kind)];
  for (liquid::WhitewaterKind kind : {liquid::WhitewaterKind::Spray, liquid::WhitewaterKind::Foam, liquid::WhitewaterKind::Bubble})
    REQUIRE(kinds[size_t(kind)] > 0);

  const std::filesystem::path folder = std::filesystem::path(LIQUID_TEST_OUTPUT_DIR) / "whitewater_export";
  std::filesystem::create_directories(folder);
  liquid::write_whitewater_ply(folder / "whitewater_00001.ply", live, liquid::WhitewaterPlyFrame{1, node.time()});
  const test::PlyPoints ply = test::read_ply_points(folder / "whitewater_00001.ply");
  REQUIRE(ply.vertices.size() == live.size());
  const glm::vec3 domain = node.scene().domain;
  std::set<std::pair<double, double>> ids;
  for (size_t i = 0; i < live.size(); ++i) {
    std::map<std::string, double> v = ply.vertices[i];
    INFO("particle " << i);
    REQUIRE((v["type"] >= 1 && v["type"] <= 3));
    REQUIRE(v["type"] == double(live[i].kind));
    REQUIRE(glm::vec3(v["x"], v["y"], v["z"]) == live[i].position);
    REQUIRE(glm::vec3(v["vx"], v["vy"], v["vz"]) == live[i].velocity);
    REQUIRE(float(v["age"]) == live[i].age);
    REQUIRE((v["age"] >= 0.0 && v["age"] <= node.time()));
    REQUIRE(glm::all(glm::greaterThanEqual(live[i].position, glm::vec3(0.0f))));
    REQUIRE(glm::all(glm::lessThanEqual(live[i].position, domain)));
    ids.insert({v["id_hi"], v["id_lo"]});
  }
  CHECK(ids.size() == live.size());  // one id a particle

#if RASTERLIQUIDS_HAVE_OPENVDB
  liquid::VolumeFrame volume = liquid::read_volume(test::gpu(), node);
  volume.foam = liquid::foam_number_density(volume, live);
  liquid::write_vdb(folder / "volume_00001.vdb", volume, liquid::VdbFrame{1, node.time(), node.scene().name});
  const liquid::VdbContents file = liquid::read_vdb(folder / "volume_00001.vdb");
  CHECK(file.grid_names == std::vector<std::string>{"density", "foam", "velocity"});  // in the order of their names
  double count = 0.0;
  for (const auto& v : file.foam) {
    REQUIRE(v.value > 0.0f);
    REQUIRE(glm::all(glm::lessThan(v.index, volume.cells)));
    count += double(v.value) * volume.cell_size * volume.cell_size * volume.cell_size;
  }
  CHECK(count == Approx(kinds[size_t(liquid::WhitewaterKind::Foam)]).epsilon(1e-4));
  // Each foam particle lies among the voxels it was spread over: its cell's centre is within one cell.
  for (const liquid::WhitewaterParticle& p : live) {
    if (p.kind != liquid::WhitewaterKind::Foam) continue;
    const glm::ivec3 cell = glm::min(glm::ivec3(p.position / volume.cell_size), volume.cells - 1);
    CHECK(volume.foam[volume.index(cell.x, cell.y, cell.z)] > 0.0f);
  }
#endif
  REQUIRE_NO_VALIDATION_MESSAGES();
}
