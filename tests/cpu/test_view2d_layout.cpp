// The 2D view's placement of the domain in a frame, on the CPU: no device needed.
#include "liquid/render/view2d.h"

#include <catch2/catch.hpp>

#include <cmath>

TEST_CASE("fit_view2d keeps the domain's aspect ratio and centres it", "[view2d]") {
  const liquid::View2dLayout wide = liquid::fit_view2d({1.0f, 0.6f}, 256, 192);
  const glm::vec2 bottom_left = wide.to_pixel({0.0f, 0.0f});
  const glm::vec2 top_right = wide.to_pixel({1.0f, 0.6f});
  // Limited by the width: letterboxed above and below, with room for the walls at the sides.
  CHECK(bottom_left.x >= 2.0f * wide.wall_pixels - 1.0f);
  CHECK(top_right.x <= 256.0f - 2.0f * wide.wall_pixels + 1.0f);
  CHECK((top_right.x - bottom_left.x) / (bottom_left.y - top_right.y) == Approx(1.0f / 0.6f).epsilon(1e-4));
  CHECK(top_right.y > 10.0f);
  CHECK(bottom_left.y < 182.0f);
  CHECK(bottom_left.y > top_right.y);  // y up on screen
  CHECK(std::abs((top_right.y + bottom_left.y) - 192.0f) <= 1.0f);
  // Limited by the height: pillarboxed.
  const liquid::View2dLayout tall = liquid::fit_view2d({0.5f, 1.0f}, 256, 192);
  CHECK(tall.to_pixel({0.0f, 0.0f}).x > 50.0f);
  CHECK(tall.to_pixel({0.0f, 1.0f}).y >= 2.0f * tall.wall_pixels - 1.0f);
}
