// Spray, foam and bubbles (Scene::whitewater, docs/whitewater.md): one-way, so the liquid is bit for
// bit the same with them; made where the dam break hits a box and not by still water; each of the
// kind its density says, inside the domain, outside the obstacle, within its life; drawn where the
// impact is (test_host.cpp: composited into a host's targets).
#include "engine/graph/transfer.h"
#include "engine/vk/commands.h"
#include "liquid/render/view2d.h"
#include "liquid/renderer.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/gpu/whitewater_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/image_compare.h"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstring>

namespace {

liquid::Scene dam_break(bool whitewater) { return test::whitewater_dam_break(whitewater); }

// Two runs' live secondary particles are the same ones, slot by slot: some of them, their ids and
// kinds equal, their positions and velocities within `tolerance` (m, m/s; 0: bit for bit).
void require_same_whitewater(const std::vector<liquid::WhitewaterParticle>& live,
                             const std::vector<liquid::WhitewaterParticle>& expected, float tolerance) {
  REQUIRE(!expected.empty());
  REQUIRE(live.size() == expected.size());
  for (size_t i = 0; i < live.size(); ++i) {
    REQUIRE(live[i].id == expected[i].id);
    REQUIRE(live[i].kind == expected[i].kind);
    REQUIRE(glm::distance(live[i].position, expected[i].position) <= tolerance);
    REQUIRE(glm::distance(live[i].velocity, expected[i].velocity) <= tolerance);
  }
}
constexpr int k_impact_steps = test::k_whitewater_impact_steps;

// rho / rho0 at p, trilinear between cell centres as the shader samples it (clamped to the grid).
float density_at(const std::vector<float>& density, glm::ivec3 cells, float h, glm::vec3 p) {
  const glm::vec3 g = p / h - 0.5f;
  const glm::ivec3 base(glm::floor(g));
  const glm::vec3 f = g - glm::vec3(base);
  float value = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::ivec3 o(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const glm::ivec3 c = glm::clamp(base + o, glm::ivec3(0), cells - 1);
    const glm::vec3 t = glm::mix(1.0f - f, f, glm::vec3(o));
    value += t.x * t.y * t.z * density[(size_t(c.z) * cells.y + c.y) * cells.x + c.x];
  }
  return value;
}

}  // namespace

TEST_CASE("whitewater leaves the liquid's results bit-identical", "[gpu][whitewater]") {
  engine::vk::Context& context = test::gpu();
  for (const liquid::Scene& with : {dam_break(true), [] {
                                      liquid::Scene s = test::shipped_scene("dam_break_2d");
                                      s.whitewater = liquid::Whitewater{};
                                      return s;
                                    }()}) {
    liquid::Scene without = with;
    without.whitewater.reset();
    liquid::LiquidNode a(context, with), b(context, without);
    test::run_steps(a, 120);
    test::run_steps(b, 120);
    REQUIRE(simulation_of(a).read_whitewater().size() > 0);  // they were there, and moving
    const liquid::ParticleSnapshot pa = a.read_particles(), pb = b.read_particles();
    REQUIRE(pa.positions.size() == pb.positions.size());
    INFO(with.name);
    CHECK(std::memcmp(pa.positions.data(), pb.positions.data(), pa.positions.size() * sizeof(glm::vec4)) == 0);
    CHECK(std::memcmp(pa.velocities.data(), pb.velocities.data(), pa.velocities.size() * sizeof(glm::vec4)) == 0);
  }
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("whitewater: the dam break's impact makes spray, foam and bubbles, each of its density's kind",
          "[gpu][whitewater]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, dam_break(true));
  liquid::Simulation& simulation = simulation_of(node);
  const liquid::Whitewater settings = *node.scene().whitewater;
  CHECK(simulation.read_whitewater().empty());  // none before anything moves
  test::run_steps(node, k_impact_steps);
  const std::vector<liquid::WhitewaterParticle> live = simulation.read_whitewater();
  const auto& setup = simulation.setup();
  const std::vector<float> density = simulation.read_density_ratio();
  const liquid::Obstacle& box = node.scene().obstacles[0];

  std::array<int, 4> kinds{};
  int density_agrees = 0, downstream = 0;
  for (const liquid::WhitewaterParticle& p : live) {
    ++kinds[size_t(p.kind)];
    INFO("at (" << p.position.x << ", " << p.position.y << ", " << p.position.z << ")");
    REQUIRE(glm::all(glm::greaterThanEqual(p.position, glm::vec3(0.0f))));
    REQUIRE(glm::all(glm::lessThanEqual(p.position, setup.domain)));
    REQUIRE(glm::any(glm::greaterThan(glm::abs(p.position - box.center), box.half_extent)));  // not inside the box
    REQUIRE(p.age >= 0.0f);
    REQUIRE(p.age <= 1.5f * settings.lifetime);
    const float rho = density_at(density, setup.grid_cells, setup.cell_size, p.position);
    const liquid::WhitewaterKind expected = rho < settings.spray_density    ? liquid::WhitewaterKind::Spray
                                            : rho > settings.bubble_density ? liquid::WhitewaterKind::Bubble
                                                                            : liquid::WhitewaterKind::Foam;
    if (expected == p.kind) ++density_agrees;
    if (p.position.x > 0.2f) ++downstream;
  }
  INFO(live.size() << " live: " << kinds[1] << " spray, " << kinds[2] << " foam, " << kinds[3] << " bubbles; "
                   << downstream << " past x = 0.2 m; kind as the density read back says: " << density_agrees);
  CHECK(live.size() > 200);
  CHECK(live.size() <= size_t(simulation.whitewater_capacity()));
  CHECK(kinds[1] > 0);
  CHECK(kinds[2] > 0);
  CHECK(kinds[3] > 0);
  // Made where the front runs and hits the box and the wall, not in the reservoir it left.
  CHECK(downstream >= int(live.size()) * 8 / 10);
  // The kind is the density's at the end of the pass's step, the density read back here, in R16F
  // and one rounding apart: nearly all agree.
  CHECK(density_agrees >= int(live.size()) * 97 / 100);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("whitewater: still water makes none, and a run makes the same particles again", "[gpu][whitewater]") {
  engine::vk::Context& context = test::gpu();
  liquid::Scene pool = test::shipped_scene("rest_pool_2d");
  pool.whitewater = liquid::Whitewater{};
  liquid::LiquidNode still(context, pool);
  test::run_steps(still, 400);
  CHECK(simulation_of(still).read_whitewater().empty());

  liquid::LiquidNode a(context, dam_break(true)), b(context, dam_break(true));
  test::run_steps(a, 150);
  test::run_steps(b, 150);
  require_same_whitewater(simulation_of(a).read_whitewater(), simulation_of(b).read_whitewater(), 0.0f);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

namespace {

constexpr uint32_t k_width = 192;
constexpr uint32_t k_height = 144;

// The node's frame with the renderer's own targets, with or without the secondary particles.
engine::vk::Rgba8Image own_frame(liquid::LiquidNode& node, bool whitewater) {
  engine::vk::Context& context = node.context();
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .whitewater = whitewater});
  engine::graph::RenderGraph graph(&context);
  const liquid::LiquidImages images = node.add_to(graph, 0);
  const liquid::RenderOutputs out = renderer.add_to(graph, images, liquid::default_camera(node));
  const engine::graph::Readback color = engine::graph::add_readback(graph, out.final, "test.color");
  graph.compile();
  engine::vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  return color.rgba8();
}

}  // namespace

TEST_CASE("whitewater is drawn where the front hits the box and the wall", "[gpu][whitewater][frames]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, dam_break(true));
  test::run_steps(node, k_impact_steps);
  const engine::vk::Rgba8Image with = own_frame(node, true), without = own_frame(node, false);
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height});
  // Where the liquid moves past x = 0.2 m: the box, the far wall and the run-up between.
  const test::BrighterPixels changed = test::brighter_pixels(with, without, renderer.view_projection(liquid::default_camera(node)),
                                          {0.2f, 0.0f, 0.0f}, node.scene().domain);
  INFO(changed.pixels << " pixels brighter with whitewater, " << changed.in_box << " of them where the impact is");
  CHECK(changed.pixels > 100);
  CHECK(changed.in_box >= changed.pixels * 9 / 10);
  const test::CompareResult result =
      test::compare_with_golden(with, "frame_whitewater_3d", {.channel_threshold = 12, .max_differing_fraction = 0.01});
  INFO(result.message);
  CHECK(result.passed);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("frame golden: the shipped 3D dam break hitting a box, with spray, foam and bubbles", "[gpu][whitewater][frames]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("dam_break_3d_whitewater"));
  test::run_steps(node, 16 * node.substeps());  // 0.54 s: the wave over the box and up the far wall
  const engine::vk::Rgba8Image with = own_frame(node, true), without = own_frame(node, false);
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height});
  const test::BrighterPixels changed = test::brighter_pixels(
      with, without, renderer.view_projection(liquid::default_camera(node)), {0.5f, 0.0f, 0.0f}, node.scene().domain);
  INFO(simulation_of(node).read_whitewater().size() << " live; " << changed.pixels << " pixels brighter with whitewater, "
                                                    << changed.in_box << " past the box's front");
  CHECK(changed.pixels > 100);
  CHECK(changed.in_box >= changed.pixels * 9 / 10);
  const test::CompareResult result = test::compare_with_golden(
      with, "frame_whitewater_dam_break_3d", {.channel_threshold = 12, .max_differing_fraction = 0.01});
  INFO(result.message);
  CHECK(result.passed);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("the 2D view draws the whitewater over the liquid, where it is", "[gpu][whitewater][view2d]") {
  engine::vk::Context& context = test::gpu();
  liquid::Scene scene = test::shipped_scene("dam_break_2d");
  scene.whitewater = liquid::Whitewater{};
  liquid::LiquidNode node(context, scene);
  test::run_steps(node, 300);  // the front has run up the far wall
  const auto live = simulation_of(node).read_whitewater();
  REQUIRE(live.size() > 20);
  const engine::vk::Rgba8Image with = own_frame(node, true), without = own_frame(node, false);
  // The view fits the domain into the frame; the box around the live particles, grown by 3 pixels,
  // holds every pixel they brightened.
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const liquid::WhitewaterParticle& p : live) {
    lo = glm::min(lo, p.position);
    hi = glm::max(hi, p.position);
  }
  const liquid::View2dLayout layout = liquid::fit_view2d(glm::vec2(node.scene().domain), k_width, k_height);
  const float scale = layout.pixels_per_metre;
  const glm::mat4 to_clip =  // x, y in metres to the frame's clip space: pixel = origin + (x, -y) scale
      glm::mat4(glm::vec4(2.0f * scale / k_width, 0, 0, 0), glm::vec4(0, -2.0f * scale / k_height, 0, 0),
                glm::vec4(0, 0, 1, 0),
                glm::vec4(2.0f * layout.origin.x / k_width - 1.0f, 2.0f * layout.origin.y / k_height - 1.0f, 0, 1));
  const glm::vec3 margin(3.0f / scale, 3.0f / scale, 0.0f);
  const test::BrighterPixels changed = test::brighter_pixels(with, without, to_clip, lo - margin, hi + margin);
  INFO(live.size() << " live; " << changed.pixels << " pixels brighter with whitewater, " << changed.in_box
                   << " within their box");
  CHECK(changed.pixels > 10);
  CHECK(changed.in_box == changed.pixels);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("a checkpoint carries the whitewater, which then continues bit for bit", "[gpu][whitewater][export]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode first(context, dam_break(true));
  test::run_steps(first, 150);
  const liquid::LiquidNode::Checkpoint saved = first.save_checkpoint();
  REQUIRE(saved.whitewater.size() == 2 * size_t(simulation_of(first).whitewater_capacity()));
  test::run_steps(first, 45);
  const auto expected = simulation_of(first).read_whitewater();
  REQUIRE(!expected.empty());

  liquid::LiquidNode second(context, dam_break(true));
  second.restore_checkpoint(saved);
  test::run_steps(second, 45);
  require_same_whitewater(simulation_of(second).read_whitewater(), expected, 0.0f);
  // Without the whitewater, or with a slot of no kind, the checkpoint is refused naming why.
  liquid::LiquidNode::Checkpoint none = saved;
  none.whitewater.clear();
  CHECK_THROWS_WITH(second.restore_checkpoint(none), Catch::Contains("the checkpoint has no whitewater"));
  liquid::LiquidNode::Checkpoint odd = saved;
  odd.whitewater[7].w = 9.0f;
  CHECK_THROWS_WITH(second.restore_checkpoint(odd), Catch::Contains("whitewater slot 7 has no kind"));
  liquid::LiquidNode plain(context, dam_break(false));
  CHECK_THROWS_WITH(plain.restore_checkpoint(saved), Catch::Contains("the checkpoint has whitewater; the scene has none"));
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

// The whitewater pass reads the grids through each 3D path's addressing (the atlas's by hand): the
// same spawns, kinds and moves on each, on a device with only that path's feature.
TEMPLATE_TEST_CASE("on each 3D path the whitewater is the same", "[gpu][whitewater][paths]", test::GeometryPath,
                   test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::LiquidNode node(context, dam_break(true), test::options_for(TestType::path));
  liquid::LiquidNode reference(test::gpu(), dam_break(true));
  test::run_steps(node, 150);
  test::run_steps(reference, 150);
  require_same_whitewater(simulation_of(node).read_whitewater(), simulation_of(reference).read_whitewater(), 1e-4f);
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}
