// The 2D view and the shallow-water height-field view on the GPU (lavapipe in CI): what the pixels
// must show given the node's density and obstacles, and goldens of small frames.
#include "engine/graph/transfer.h"
#include "engine/vk/commands.h"
#include "liquid/physics/obstacles.h"
#include "liquid/render/height_field.h"
#include "liquid/render/view2d.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/image_compare.h"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <span>

using engine::graph::ImageHandle;
using engine::vk::Rgba8Image;

namespace {

constexpr uint32_t k_width = 256;
constexpr uint32_t k_height = 192;

// Imports the node's current state (0 steps), adds `view`, reads its output back.
Rgba8Image render(liquid::LiquidNode& node,
                  const std::function<ImageHandle(engine::graph::RenderGraph&, const liquid::LiquidImages&)>& view) {
  engine::vk::Context& context = test::gpu();
  engine::graph::RenderGraph graph(&context);
  const liquid::LiquidImages images = node.add_to(graph, 0);
  const engine::graph::Readback readback = engine::graph::add_readback(graph, view(graph, images));
  graph.compile();
  engine::vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  return readback.rgba8();
}

glm::ivec3 pixel(const Rgba8Image& image, int x, int y) {
  const size_t i = (size_t(y) * image.width + size_t(x)) * 4;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

bool near_colour(glm::ivec3 actual, glm::vec3 expected, int tolerance) {
  const glm::ivec3 e = glm::ivec3(glm::round(expected * 255.0f));
  const glm::ivec3 d = glm::abs(actual - e);
  return d.x <= tolerance && d.y <= tolerance && d.z <= tolerance;
}

bool is_grey(glm::ivec3 c) { return std::abs(c.r - c.g) <= 6 && std::abs(c.g - c.b) <= 8 && c.r >= 60 && c.r <= 160; }
bool is_blue(glm::ivec3 c) { return c.b > c.r + 40 && c.b > c.g; }

// The colours view2d.frag and height_field.frag paint where nothing else is.
const glm::vec3 k_background(0.125f, 0.140f, 0.175f);
const glm::vec3 k_letterbox(0.075f, 0.085f, 0.105f);
const glm::vec3 k_wall(0.62f, 0.66f, 0.72f);
const glm::vec3 k_sky(0.70f, 0.79f, 0.89f);

// Smallest and largest rho / rho0 among the grid cells around `p` (what bilinear filtering can
// return there, with one cell of slack).
std::pair<float, float> density_range(const liquid::SimulationSetup& setup, const std::vector<float>& density,
                                      glm::vec2 p) {
  const glm::ivec2 n(setup.grid_cells.x, setup.grid_cells.y);
  const glm::ivec2 c = glm::ivec2(glm::floor(p / setup.cell_size));
  float lo = 1e30f, hi = -1e30f;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const glm::ivec2 q = glm::clamp(c + glm::ivec2(dx, dy), glm::ivec2(0), n - 1);
      const float value = density[size_t(q.y) * size_t(n.x) + size_t(q.x)];
      lo = std::min(lo, value);
      hi = std::max(hi, value);
    }
  return {lo, hi};
}

// Signed distance (m) to the nearest obstacle of the node at its current time.
float nearest_obstacle(const liquid::LiquidNode& node, glm::vec2 p) {
  const auto poses = node.obstacle_poses(node.time());
  float d = 1e30f;
  for (size_t i = 0; i < poses.size(); ++i)
    d = std::min(d, liquid::obstacle_distance(node.scene().obstacles[i], poses[i], glm::vec3(p, 0.0f), 2));
  return d;
}

// Replaces the node's density grid with rho / rho0 = field(cell centre). The golden tests draw such
// fields, so that a golden changes with the view alone, not with the solver or a scene's tuning.
void set_density(liquid::LiquidNode& node, const std::function<float(glm::vec2)>& field) {
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  const int nx = setup.grid_cells.x, ny = setup.grid_cells.y;
  std::vector<uint16_t> halves(size_t(nx) * size_t(ny));
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      halves[size_t(y) * size_t(nx) + size_t(x)] =
          uint16_t(glm::packHalf1x16(field((glm::vec2(float(x), float(y)) + 0.5f) * setup.cell_size)));
  engine::graph::upload_image(test::gpu(), simulation_of(node).state().density, std::as_bytes(std::span(halves)));
}

// 0 outside, 1 inside, a linear ramp `width` wide across the surface at signed distance 0.
float ramp(float inside_distance, float width) { return std::clamp(0.5f + inside_distance / width, 0.0f, 1.0f); }

float square(float x) { return x * x; }

}  // namespace

TEST_CASE("2D view of obstacles_2d: liquid where the density is high, grey obstacles, walls", "[gpu][view2d]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("obstacles_2d"));
  test::run_steps(node, 40);
  liquid::View2dPass pass(context, node);
  const liquid::RenderSettings settings{.width = k_width, .height = k_height, .fxaa = false};
  const Rgba8Image image = render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings); });
  REQUIRE(image.width == k_width);
  REQUIRE(image.height == k_height);

  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  const std::vector<float> density = node.read_density_ratio();
  const liquid::View2dLayout layout = liquid::fit_view2d(glm::vec2(setup.domain), k_width, k_height);
  const float metres_per_pixel = 1.0f / layout.pixels_per_metre;

  // Every pixel well inside the domain: blue where the liquid is certain, the background where the
  // grid is empty, grey deep inside an obstacle.
  int liquid_pixels = 0, empty_pixels = 0, obstacle_pixels = 0;
  int wrong_liquid = 0, wrong_empty = 0, wrong_obstacle = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const glm::vec2 p = (glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - layout.origin) * glm::vec2(1.0f, -1.0f) *
                          metres_per_pixel;
      if (glm::any(glm::lessThan(p, glm::vec2(2.0f * metres_per_pixel))) ||
          glm::any(glm::greaterThan(p, glm::vec2(setup.domain) - 2.0f * metres_per_pixel)))
        continue;
      const glm::ivec3 c = pixel(image, int(x), int(y));
      const float obstacle = nearest_obstacle(node, p);
      if (obstacle < -2.0f * metres_per_pixel) {
        ++obstacle_pixels;
        wrong_obstacle += is_grey(c) ? 0 : 1;
        continue;
      }
      if (obstacle < 2.0f * metres_per_pixel) continue;  // the obstacle's anti-aliased edge
      const auto [lo, hi] = density_range(setup, density, p);
      if (lo > settings.iso_level + 0.1f) {
        ++liquid_pixels;
        wrong_liquid += is_blue(c) ? 0 : 1;
      } else if (hi < settings.iso_level - 0.1f) {
        ++empty_pixels;
        wrong_empty += near_colour(c, k_background, 2) ? 0 : 1;
      }
    }
  INFO("liquid " << liquid_pixels << " (" << wrong_liquid << " not blue), empty " << empty_pixels << " ("
                 << wrong_empty << " not background), obstacle " << obstacle_pixels << " (" << wrong_obstacle
                 << " not grey)");
  CHECK(liquid_pixels > 1000);
  CHECK(empty_pixels > 5000);
  CHECK(obstacle_pixels > 300);
  CHECK(wrong_liquid == 0);
  CHECK(wrong_empty == 0);
  CHECK(wrong_obstacle == 0);

  // The sphere's centre is grey; the tank's walls flank the domain; letterbox bars above and below.
  const glm::vec2 sphere = layout.to_pixel(glm::vec2(node.obstacle_poses(node.time())[0].center));
  CHECK(is_grey(pixel(image, int(sphere.x), int(sphere.y))));
  const glm::vec2 left_wall = layout.to_pixel({0.0f, 0.5f * setup.domain.y}) - glm::vec2(0.5f * layout.wall_pixels, 0.0f);
  const glm::vec2 right_wall =
      layout.to_pixel({setup.domain.x, 0.5f * setup.domain.y}) + glm::vec2(0.5f * layout.wall_pixels, 0.0f);
  const glm::vec2 floor = layout.to_pixel({0.5f * setup.domain.x, 0.0f}) + glm::vec2(0.0f, 0.5f * layout.wall_pixels);
  CHECK(near_colour(pixel(image, int(left_wall.x), int(left_wall.y)), k_wall, 2));
  CHECK(near_colour(pixel(image, int(right_wall.x), int(right_wall.y)), k_wall, 2));
  CHECK(near_colour(pixel(image, int(floor.x), int(floor.y)), k_wall, 2));
  CHECK(near_colour(pixel(image, int(k_width / 2), 1), k_letterbox, 2));
  CHECK(near_colour(pixel(image, int(k_width / 2), int(k_height) - 2), k_letterbox, 2));

  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("2D view draws the active particles as points over the liquid", "[gpu][view2d]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("obstacles_2d"));
  test::run_steps(node, 40);
  liquid::View2dPass pass(context, node);
  liquid::RenderSettings settings{.width = k_width, .height = k_height, .fxaa = false};
  const Rgba8Image plain = render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings); });
  settings.draw_particles = true;
  const Rgba8Image dotted = render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings); });

  // Pixels within a point's reach of some particle may change; nothing else may.
  const liquid::View2dLayout layout = liquid::fit_view2d(glm::vec2(simulation_of(node).setup().domain), k_width, k_height);
  std::vector<uint8_t> reachable(size_t(k_width) * k_height, 0);
  const liquid::ParticleSnapshot particles = node.read_particles();
  REQUIRE(int(particles.positions.size()) == node.active_particles());
  for (const glm::vec4& p : particles.positions) {
    const glm::vec2 centre = layout.to_pixel(glm::vec2(p));
    for (int y = int(centre.y) - 4; y <= int(centre.y) + 4; ++y)
      for (int x = int(centre.x) - 4; x <= int(centre.x) + 4; ++x)
        if (x >= 0 && y >= 0 && x < int(k_width) && y < int(k_height)) reachable[size_t(y) * k_width + size_t(x)] = 1;
  }
  int changed = 0, changed_elsewhere = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const glm::ivec3 a = pixel(plain, int(x), int(y)), b = pixel(dotted, int(x), int(y));
      if (a == b) continue;
      ++changed;
      if (!reachable[size_t(y) * k_width + x]) ++changed_elsewhere;
      // Points are light: they only brighten.
      CHECK(b.r + b.g + b.b > a.r + a.g + a.b);
    }
  INFO("changed " << changed << ", of which away from every particle " << changed_elsewhere);
  CHECK(changed > 1000);
  CHECK(changed_elsewhere == 0);

  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("height-field view of shallow_water: sky, sandy ground and water where it is deep", "[gpu][height_field]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, test::shipped_scene("shallow_water"));
  test::run_steps(node, 16);
  liquid::HeightFieldPass pass(context, node);
  const liquid::RenderSettings settings{.width = k_width, .height = k_height, .fxaa = false};
  const liquid::CameraView camera = liquid::default_height_field_camera(node.scene(), simulation_of(node).setup());
  const Rgba8Image image =
      render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings, camera); });

  int sky = 0, water = 0, sand = 0;
  for (uint32_t y = 0; y < k_height; ++y)
    for (uint32_t x = 0; x < k_width; ++x) {
      const glm::ivec3 c = pixel(image, int(x), int(y));
      sky += near_colour(c, k_sky, 1) ? 1 : 0;
      water += c.b > c.r + 40 && !near_colour(c, k_sky, 1) ? 1 : 0;
      sand += c.r > c.b + 30 ? 1 : 0;
    }
  const int pixels = int(k_width * k_height);
  INFO("sky " << sky << ", water " << water << ", sand " << sand << " of " << pixels);
  CHECK(sky > pixels / 20);
  CHECK(water > pixels / 5);
  CHECK(sand > pixels / 200);
  CHECK(near_colour(pixel(image, int(k_width / 2), 0), k_sky, 1));  // above the plane's far edge

  // The plane's centre (deep water) projects onto water; the middle of the near side wall (the
  // ground's slab below the bed) onto sand.
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  const std::vector<float> density = node.read_density_ratio();
  const glm::ivec2 n(setup.grid_cells.x, setup.grid_cells.y);
  const float centre_depth = setup.rest_depth * density[size_t(n.y / 2) * size_t(n.x) + size_t(n.x / 2)];
  REQUIRE(centre_depth > 2.0f * liquid::HeightFieldPass::k_dry_fraction * setup.rest_depth);
  const glm::mat4 vp = liquid::view_projection(camera, float(k_width) / float(k_height), 0.01f, 100.0f);
  auto project = [&](glm::vec3 world) {
    const glm::vec4 clip = vp * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::ivec2((ndc * 0.5f + 0.5f) * glm::vec2(k_width, k_height));
  };
  const float ground_centre = liquid::ground_height(node.scene(), glm::vec2(setup.domain) * 0.5f);
  const glm::ivec2 centre = project({0.5f * setup.domain.x, ground_centre + centre_depth, 0.5f * setup.domain.y});
  const glm::ivec3 centre_colour = pixel(image, centre.x, centre.y);
  INFO("centre pixel " << centre.x << "," << centre.y << " = " << centre_colour.r << "," << centre_colour.g << ","
                       << centre_colour.b);
  CHECK(is_blue(centre_colour));
  const glm::ivec2 side = project({0.5f * setup.domain.x, -0.5f * setup.rest_depth, setup.domain.y});
  const glm::ivec3 side_colour = pixel(image, side.x, side.y);
  INFO("near side pixel " << side.x << "," << side.y << " = " << side_colour.r << "," << side_colour.g << ","
                          << side_colour.b);
  CHECK(side_colour.r > side_colour.b + 30);

  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("the views refuse scenes they cannot show", "[gpu][view2d][height_field]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode liquid_2d(context, test::shipped_scene("obstacles_2d"));
  CHECK_THROWS_AS(liquid::HeightFieldPass(context, liquid_2d), liquid::UsageError);
  liquid::LiquidNode liquid_3d(context, test::shipped_scene("small_3d"));
  CHECK_THROWS_AS(liquid::View2dPass(context, liquid_3d), liquid::UsageError);
  REQUIRE_NO_VALIDATION_MESSAGES();
}


TEST_CASE("2D view golden: a wave, a droplet, a thin sheet, obstacles and particles", "[gpu][view2d]") {
  engine::vk::Context& context = test::gpu();
  // Three obstacles (a sphere breaking the surface, a submerged box, merged metaballs in the air)
  // and a block of particles under the surface.
  const liquid::Scene scene = liquid::parse_scene(R"({
    "name": "view2d golden", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 2, "domain": [1.0, 0.6], "grid_resolution": 128,
    "particle_spacing": 0.01, "density": 1000, "stiffness": 50, "substeps": 1,
    "fluid_blocks": [ { "min": [0.03, 0.03], "max": [0.33, 0.2] } ],
    "obstacles": [
      { "shape": "sphere", "center": [0.55, 0.26], "radius": 0.06 },
      { "shape": "box", "center": [0.82, 0.1], "half_extent": [0.07, 0.04] },
      { "shape": "metaballs", "balls": [ { "center": [0.64, 0.45], "radius": 0.075 },
                                         { "center": [0.73, 0.47], "radius": 0.065 } ], "threshold": 0.3 }
    ] })",
                                                  "view2d_golden.json");
  liquid::LiquidNode node(context, scene);
  const float h = simulation_of(node).setup().cell_size;
  // A wave piled up on the left, slightly compressed at depth, a droplet and a sheet 1.5 cells thick.
  const glm::vec2 drop(0.36f, 0.46f), sheet_a(0.40f, 0.36f), sheet_b(0.50f, 0.41f);
  set_density(node, [&](glm::vec2 p) {
    const float surface = 0.24f + 0.1f * std::exp(-square((p.x - 0.15f) / 0.15f)) +
                          0.015f * std::sin(2.0f * 3.14159265f * p.x / 0.17f);
    const float below = surface - p.y;
    const float body = ramp(below, 2.0f * h) * (1.0f + 0.35f * std::clamp(below / 0.3f, 0.0f, 1.0f));
    const float droplet = ramp(0.025f - glm::length(p - drop), 2.0f * h);
    const glm::vec2 ab = sheet_b - sheet_a;
    const float t = std::clamp(glm::dot(p - sheet_a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    const float sheet = ramp(0.75f * h - glm::length(p - (sheet_a + t * ab)), 2.0f * h);
    return std::max({body, droplet, sheet});
  });
  liquid::View2dPass pass(context, node);
  liquid::RenderSettings settings{.width = k_width, .height = k_height, .fxaa = false};
  const Rgba8Image image = render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings); });
  settings.draw_particles = true;
  const Rgba8Image dotted = render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings); });

  const liquid::View2dLayout layout = liquid::fit_view2d({1.0f, 0.6f}, k_width, k_height);
  auto at = [&](const Rgba8Image& frame, glm::vec2 p) {
    const glm::vec2 q = layout.to_pixel(p);
    return pixel(frame, int(q.x), int(q.y));
  };
  CHECK(is_blue(at(image, drop)));
  CHECK(is_blue(at(image, {0.15f, 0.2f})));
  CHECK(near_colour(at(image, {0.3f, 0.55f}), k_background, 2));
  CHECK(is_grey(at(image, {0.55f, 0.26f})));
  CHECK(is_grey(at(image, {0.82f, 0.1f})));
  CHECK(is_grey(at(image, {0.685f, 0.46f})));  // between the metaballs: they merge
  // The sheet, thinner than two pixels, is still drawn: its centre is bluer than the background.
  const glm::ivec3 sheet = at(image, 0.5f * (sheet_a + sheet_b));
  CHECK(sheet.b > 90);

  const test::CompareResult plain =
      test::compare_with_golden(image, "view2d_obstacles", {.channel_threshold = 8, .max_differing_fraction = 0.01});
  INFO(plain.message);
  CHECK(plain.passed);
  const test::CompareResult particles = test::compare_with_golden(
      dotted, "view2d_obstacles_particles", {.channel_threshold = 8, .max_differing_fraction = 0.01});
  INFO(particles.message);
  CHECK(particles.passed);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("height-field golden: waves around a dry island over a sandy bed", "[gpu][height_field]") {
  engine::vk::Context& context = test::gpu();
  const liquid::Scene scene = liquid::parse_scene(R"({
    "name": "height field golden", "splat": "point_sprite", "dimension": 2, "mode": "shallow_water", "domain": [1.0, 1.0],
    "grid_resolution": 128, "particle_spacing": 0.01, "density": 1000, "rest_depth": 0.05,
    "time_step": 0.001, "substeps": 1,
    "fluid_blocks": [ { "min": [0.0, 0.0], "max": [1.0, 1.0] } ],
    "ground": [ { "center": [0.75, 0.3], "height": 0.09, "width": 0.07 },
                { "center": [0.25, 0.7], "height": 0.035, "width": 0.08 } ] })",
                                                  "height_field_golden.json");
  liquid::LiquidNode node(context, scene);
  const float rest_depth = scene.rest_depth;
  // Still water at the rest depth, a ring wave and a hump around (0.4, 0.45), gentle ripples; the
  // island (0.09 m) stands out of it.
  const glm::vec2 centre(0.4f, 0.45f);
  set_density(node, [&](glm::vec2 p) {
    const float r = glm::length(p - centre);
    const float level = rest_depth + 0.018f * std::exp(-square((r - 0.22f) / 0.035f)) +
                        0.03f * std::exp(-square(r / 0.06f)) + 0.0008f * std::sin(2.0f * 3.14159265f * (p.x + 2.0f * p.y) / 0.25f);
    return std::max(level - liquid::ground_height(scene, p), 0.0f) / rest_depth;
  });
  liquid::HeightFieldPass pass(context, node);
  const liquid::RenderSettings settings{.width = k_width, .height = k_height, .fxaa = false};
  const liquid::CameraView camera = liquid::default_height_field_camera(node.scene(), simulation_of(node).setup());
  const Rgba8Image image =
      render(node, [&](auto& graph, const auto& images) { return pass.add_to(graph, images, settings, camera); });

  const glm::mat4 vp = liquid::view_projection(camera, float(k_width) / float(k_height), 0.01f, 100.0f);
  auto at = [&](glm::vec3 world) {
    const glm::vec4 clip = vp * glm::vec4(world, 1.0f);
    const glm::vec2 q = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(k_width, k_height);
    return pixel(image, int(q.x), int(q.y));
  };
  const glm::ivec3 island = at({0.75f, 0.09f, 0.3f});
  const glm::ivec3 water = at({0.4f, rest_depth + 0.03f, 0.45f});
  INFO("island " << island.r << "," << island.g << "," << island.b << "; water " << water.r << "," << water.g << ","
                 << water.b);
  CHECK(island.r > island.b + 40);  // dry sand
  CHECK(water.b > water.r + 40);
  CHECK(near_colour(pixel(image, int(k_width / 2), 0), k_sky, 1));

  const test::CompareResult golden = test::compare_with_golden(
      image, "height_field_shallow_water", {.channel_threshold = 8, .max_differing_fraction = 0.01});
  INFO(golden.message);
  CHECK(golden.passed);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
