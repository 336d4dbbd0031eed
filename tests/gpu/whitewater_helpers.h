// The whitewater tests' scene (a small 3D dam break hitting a box) and the measure of where the
// secondary particles show in a frame, shared by test_whitewater.cpp and test_host.cpp.
#pragma once

#include "engine/vk/image.h"
#include "liquid/scene.h"

#include <glm/glm.hpp>

namespace test {

// A small 3D dam break in the shipped dam break's regime and cells (1.56 cm), a column 0.3 m tall
// whose front hits a box 0.19 m downstream at about 0.2 s and throws spray; with "whitewater": {} when `whitewater`.
inline liquid::Scene whitewater_dam_break(bool whitewater = true) {
  liquid::Scene scene = liquid::parse_scene(R"({
  "name": "whitewater dam break", "dimension": 3, "domain": [0.5, 0.4, 0.25], "grid_resolution": 32,
  "particle_spacing": 0.0104, "density": 1000, "stiffness": 14.112, "gamma": 5, "kernel_radius_cells": 3,
  "pic_ratio": 0.05, "pic_ratio_reference_step": 0.0002801, "pressure_force": "splat_adjoint", "splat": "separable",
  "projection_iterations": 0, "time_step": 0.002241, "substeps": 15, "wall_margin_cells": 0.3,
  "fluid_blocks": [ { "min": [0.0, 0.0, 0.0], "max": [0.16, 0.3, 0.25] } ],
  "obstacles": [ { "shape": "box", "center": [0.35, 0.05, 0.125], "half_extent": [0.02, 0.05, 0.05] } ],
  "whitewater": {},
  "camera": { "position": [0.25, 0.45, 0.9], "target": [0.25, 0.1, 0.12], "fov_y_degrees": 45 } })",
                                                      "whitewater_dam_break.json");
  if (!whitewater) scene.whitewater.reset();
  return scene;
}
// Steps to 0.47 s: the front has hit the box and the far wall.
constexpr int k_whitewater_impact_steps = 210;

// The pixels of `with` brighter than in `without` (the sum of the channels by at least 3 x 12
// levels), and how many of them lie in the screen rectangle of the box [lo, hi] seen through
// `view_projection`.
struct BrighterPixels {
  size_t pixels = 0, in_box = 0;
};
inline BrighterPixels brighter_pixels(const engine::vk::Rgba8Image& with, const engine::vk::Rgba8Image& without,
                                      const glm::mat4& view_projection, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec2 size(with.width, with.height);
  glm::vec2 min_px(1e9f), max_px(-1e9f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const glm::vec4 clip = view_projection * glm::vec4(corner, 1.0f);
    const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
    min_px = glm::min(min_px, px);
    max_px = glm::max(max_px, px);
  }
  BrighterPixels b;
  for (uint32_t y = 0; y < with.height; ++y)
    for (uint32_t x = 0; x < with.width; ++x) {
      const size_t i = (size_t(y) * with.width + x) * 4;
      const int gain = (with.pixels[i] + with.pixels[i + 1] + with.pixels[i + 2]) -
                       (without.pixels[i] + without.pixels[i + 1] + without.pixels[i + 2]);
      if (gain < 3 * 12) continue;
      ++b.pixels;
      if (float(x) >= min_px.x && float(x) <= max_px.x && float(y) >= min_px.y && float(y) <= max_px.y) ++b.in_box;
    }
  return b;
}

}  // namespace test
