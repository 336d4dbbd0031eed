// Whole frames as a host makes them: the solver's steps, then LiquidRenderer (raymarch, 2D view
// or height field) and FXAA, all on one render graph. Small scenes and frames so lavapipe runs them
// in seconds; goldens catch a change in the solver or in the shading.
#include "engine/graph/transfer.h"
#include "engine/vk/commands.h"
#include "liquid/renderer.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/gpu.h"
#include "tests/support/image_compare.h"

#include <catch2/catch.hpp>

#include <glm/glm.hpp>

#include <cstring>

using engine::vk::Rgba8Image;

namespace {

constexpr uint32_t k_width = 192;
constexpr uint32_t k_height = 144;
// A frame after tens of solver steps: a few pixels along the surface may move with the driver's
// vector path, so the tolerance allows 1% of the pixels to differ by more than 12 levels.
constexpr test::CompareTolerance k_frame_tolerance{.channel_threshold = 12, .max_differing_fraction = 0.01};

struct Frame {
  Rgba8Image color;              // after FXAA
  std::vector<float> depth;      // 3D only: the raymarch's depth buffer, 1 = nothing hit
};

// Runs `steps` steps in frames of at most the scene's substeps, then renders the last state.
Frame step_and_render(liquid::LiquidNode& node, int steps, bool fxaa = true) {
  engine::vk::Context& context = node.context();
  if (steps > 0) test::run_steps(node, steps);
  liquid::LiquidRenderer renderer(context, node, {.width = k_width, .height = k_height, .fxaa = fxaa});
  engine::graph::RenderGraph graph(&context);
  const liquid::LiquidImages images = node.add_to(graph, 0);
  const liquid::RenderOutputs out = renderer.add_to(graph, images, liquid::default_camera(node));
  const engine::graph::Readback color = engine::graph::add_readback(graph, out.final, "test.color");
  std::optional<engine::graph::Readback> depth;
  if (out.depth.valid()) depth = engine::graph::add_readback(graph, out.depth, "test.depth");
  graph.compile();
  engine::vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  Frame frame{color.rgba8(), {}};
  if (depth) {
    frame.depth.resize(size_t(k_width) * k_height);
    std::memcpy(frame.depth.data(), depth->bytes().data(), frame.depth.size() * sizeof(float));
  }
  return frame;
}

void check_golden(const Rgba8Image& image, const std::string& name) {
  const test::CompareResult result = test::compare_with_golden(image, name, k_frame_tolerance);
  INFO(result.message);
  CHECK(result.passed);
}

// A pixel that reads as water: clearly bluer than it is red, and not the pale blue-grey of a sky
// (the height field's clear colour is (178, 201, 227); the raymarch's sky is as pale or paler).
bool is_water(const uint8_t* rgba) {
  const int r = rgba[0], b = rgba[2];
  return b > r + 30 && r < 150;
}

// Fraction of pixels that read as water.
double water_fraction(const Rgba8Image& image) {
  size_t count = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4)
    if (is_water(&image.pixels[i])) ++count;
  return double(count) / double(size_t(image.width) * image.height);
}

// `steps` steps of `node`, then its frame: water on more than 5% of it, and matching the golden `name`.
void check_frame_golden(liquid::LiquidNode& node, int steps, const std::string& name) {
  const Frame frame = step_and_render(node, steps);
  CHECK(water_fraction(frame.color) > 0.05);
  check_golden(frame.color, name);
}

}  // namespace

// The 3D goldens hold on every 3D path (liquid/solver/grid_layout.h) with the same golden and tolerance:
// the paths differ only in how a cell is addressed and, on the atlas, in interpolating between
// slices by hand, which moves no pixel past k_frame_tolerance (the paths agree within
// test_grid_paths.cpp's bounds).
TEMPLATE_TEST_CASE("frame golden: 3D dam break, raymarched with FXAA", "[gpu][frames][raymarch][paths]", test::GeometryPath,
                   test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::LiquidNode node(context, liquid::parse_scene(R"({
    "name": "frame golden 3D", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 3, "domain": [0.5, 0.3, 0.25], "grid_resolution": 32,
    "particle_spacing": 0.008, "density": 1000, "stiffness": 12, "time_step": 0.0005, "substeps": 20,
    "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.16, 0.2, 0.25] } ],
    "camera": { "position": [0.25, 0.35, 0.8], "target": [0.25, 0.08, 0.12], "fov_y_degrees": 45 } })",
                                                         "frame_golden_3d.json"),
                          test::options_for(TestType::path));
  const Frame frame = step_and_render(node, 60);

  // The liquid covers part of the frame and reads as water, and the raymarch wrote depth wherever
  // it drew liquid, so a host can composite its own geometry.
  const double water = water_fraction(frame.color);
  REQUIRE(frame.depth.size() == size_t(k_width) * k_height);
  size_t water_pixels = 0, water_with_depth = 0;
  for (size_t i = 0; i < frame.depth.size(); ++i) {
    if (!is_water(&frame.color.pixels[i * 4])) continue;
    ++water_pixels;
    if (frame.depth[i] < 1.0f) ++water_with_depth;
  }
  INFO("water colour on " << water * 100.0 << "% of the pixels");
  CHECK(water > 0.03);
  CHECK(water < 0.6);
  // FXAA blends colour across the silhouette, where the depth is the raw one: allow a margin.
  CHECK(water_with_depth >= water_pixels * 8 / 10);
  check_golden(frame.color, "frame_dam_break_3d");
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEMPLATE_TEST_CASE("frame golden: 3D sphere obstacle in the liquid, raymarched", "[gpu][frames][raymarch][paths]",
                   test::GeometryPath, test::VertexLayerPath, test::AtlasPath) {
  engine::vk::Context& context = test::gpu_for(TestType::path);
  liquid::LiquidNode node(context, liquid::parse_scene(R"({
    "name": "frame golden 3D obstacle", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 3, "domain": [0.4, 0.3, 0.3], "grid_resolution": 28,
    "particle_spacing": 0.009, "density": 1000, "stiffness": 12, "time_step": 0.0005, "substeps": 20,
    "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.4, 0.08, 0.3] } ],
    "obstacles": [ { "shape": "sphere", "center": [0.2, 0.09, 0.15], "radius": 0.06 } ],
    "camera": { "position": [0.2, 0.4, 0.75], "target": [0.2, 0.06, 0.15], "fov_y_degrees": 45 } })",
                                                         "frame_golden_3d_obstacle.json"),
                          test::options_for(TestType::path));
  check_frame_golden(node, 40, "frame_obstacle_3d");
  REQUIRE_NO_VALIDATION_MESSAGES_ON(context);
}

TEST_CASE("frame golden: 2D dam break with obstacles, 2D view with FXAA", "[gpu][frames][view2d]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, liquid::parse_scene(R"({
    "name": "frame golden 2D", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 2, "domain": [1.0, 0.6], "grid_resolution": 96,
    "particle_spacing": 0.008, "density": 1000, "stiffness": 20, "time_step": 0.0006, "substeps": 25,
    "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.3, 0.4] } ],
    "obstacles": [ { "shape": "sphere", "center": [0.6, 0.1], "radius": 0.07 },
                   { "shape": "box", "center": [0.85, 0.25], "half_extent": [0.06, 0.03] } ] })",
                                                         "frame_golden_2d.json"));
  check_frame_golden(node, 150, "frame_dam_break_2d");
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("frame golden: shallow water over a hill, height field with FXAA", "[gpu][frames][height_field]") {
  engine::vk::Context& context = test::gpu();
  liquid::LiquidNode node(context, liquid::parse_scene(R"({
    "name": "frame golden shallow water", "dimension": 2, "mode": "shallow_water", "splat": "point_sprite", "domain": [1.0, 1.0],
    "grid_resolution": 64, "particle_spacing": 0.0125, "density": 1000, "rest_depth": 0.05,
    "time_step": 0.002, "substeps": 10,
    "fluid_blocks": [ { "min": [0.0, 0.0], "max": [0.5, 1.0] } ],
    "ground": [ { "center": [0.7, 0.5], "height": 0.06, "width": 0.1 } ] })",
                                                         "frame_golden_shallow_water.json"));
  check_frame_golden(node, 60, "frame_shallow_water");
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("FXAA changes the raymarched frame only along edges", "[gpu][frames][raymarch]") {
  engine::vk::Context& context = test::gpu();
  const auto scene = liquid::parse_scene(R"({
    "name": "fxaa 3D", "pressure_force": "chapter", "splat": "point_sprite", "dimension": 3, "domain": [0.4, 0.3, 0.3], "grid_resolution": 24,
    "particle_spacing": 0.01, "density": 1000, "stiffness": 12, "time_step": 0.0005, "substeps": 10,
    "fluid_blocks": [ { "min": [0.1, 0.0, 0.1], "max": [0.3, 0.15, 0.2] } ] })",
                                         "fxaa_3d.json");
  liquid::LiquidNode with(context, scene), without(context, scene);
  const Frame smooth = step_and_render(with, 10, true);
  const Frame raw = step_and_render(without, 10, false);
  // Same state, same view: FXAA touches some pixels (the silhouette) and leaves most alone.
  const test::CompareResult diff = test::compare_images(smooth.color, raw.color, {.channel_threshold = 2});
  INFO(diff.message);
  CHECK(diff.differing_fraction > 0.0005);
  CHECK(diff.differing_fraction < 0.2);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
