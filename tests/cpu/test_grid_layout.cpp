// The CPU side of the 3D paths: which path a device gets, the atlas's tiling and its read-back
// conversion, and the splat format's fallback.
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/state.h"

#include <catch2/catch.hpp>

#include <set>

using liquid::GridLayout;
using liquid::GridPath;

TEST_CASE("the 3D path follows the device's features unless one is forced", "[grid_layout]") {
  using liquid::choose_grid_path;
  CHECK(choose_grid_path({true, true}, std::nullopt) == GridPath::VertexLayer);
  CHECK(choose_grid_path({true, false}, std::nullopt) == GridPath::GeometryShader);
  CHECK(choose_grid_path({false, false}, std::nullopt) == GridPath::Atlas);
  CHECK(choose_grid_path({true, true}, GridPath::GeometryShader) == GridPath::GeometryShader);
  CHECK(choose_grid_path({false, false}, GridPath::Atlas) == GridPath::Atlas);
  CHECK_THROWS_WITH(choose_grid_path({false, true}, GridPath::GeometryShader), Catch::Contains("geometryShader"));
  CHECK_THROWS_WITH(choose_grid_path({true, false}, GridPath::VertexLayer), Catch::Contains("shaderOutputLayer"));
  for (GridPath path : {GridPath::GeometryShader, GridPath::VertexLayer, GridPath::Atlas})
    CHECK(liquid::parse_grid_path(liquid::grid_path_name(path), "--3d-path") == path);
  CHECK_THROWS_WITH(liquid::parse_grid_path("gs", "--3d-path"),
                    "--3d-path: 'gs' is not a 3D path (geometry, vertex-layer or atlas)");
}

TEST_CASE("the atlas tiles the slices in a near-square grid and maps every cell to its own texel", "[grid_layout]") {
  struct Case {
    int nz;
    glm::ivec2 tiles;
  };
  for (const Case c : {Case{1, {1, 1}}, Case{2, {2, 1}}, Case{12, {4, 3}}, Case{16, {4, 4}}, Case{17, {5, 4}},
                       Case{64, {8, 8}}, Case{65, {9, 8}}}) {
    INFO("nz " << c.nz);
    const GridLayout layout(3, {5, 3, c.nz}, GridPath::Atlas);
    CHECK(layout.tiles == c.tiles);
    const engine::vk::ImageDesc desc = layout.image_desc(VK_FORMAT_R32_SFLOAT, 0);
    CHECK(desc.kind == engine::vk::ImageKind::Image2D);
    CHECK(desc.width == uint32_t(5 * c.tiles.x));
    CHECK(desc.height == uint32_t(3 * c.tiles.y));
    std::set<size_t> texels;
    std::vector<int> image(size_t(desc.width) * desc.height, -1);
    int i = 0;
    for (int z = 0; z < c.nz; ++z)
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
          const size_t t = layout.texel_index(x, y, z);
          REQUIRE(t < image.size());
          texels.insert(t);
          image[t] = i++;
        }
    CHECK(texels.size() == size_t(15 * c.nz));  // no two cells share a texel
    // Slice z's cell (x, y) sits at x + (z % columns) * nx, y + (z / columns) * ny.
    CHECK(layout.texel_index(1, 2, c.nz - 1) ==
          size_t(1 + ((c.nz - 1) % c.tiles.x) * 5 + (2 + ((c.nz - 1) / c.tiles.x) * 3) * desc.width));
    // The read-back conversion returns cell order: x fastest, then y, then z.
    const std::vector<int> linear = layout.to_linear(image);
    REQUIRE(linear.size() == size_t(15 * c.nz));
    for (size_t k = 0; k < linear.size(); ++k) REQUIRE(linear[k] == int(k));
  }
  // The layered paths and 2D scenes keep their images as they are.
  const GridLayout layered(3, {5, 3, 4}, GridPath::GeometryShader);
  CHECK(layered.image_desc(VK_FORMAT_R32_SFLOAT, 0).kind == engine::vk::ImageKind::Image3D);
  CHECK(layered.texel_index(1, 2, 3) == size_t(1 + 5 * (2 + 3 * 3)));
  const GridLayout flat(2, {5, 3, 1}, GridPath::Atlas);
  CHECK(!flat.atlas());
  CHECK(flat.image_desc(VK_FORMAT_R32_SFLOAT, 0).width == 5u);
}

TEST_CASE("the splat format falls back to RGBA16F only where RGBA32F cannot be blended and it was not asked for",
          "[grid_layout]") {
  using liquid::SplatFormat;
  const auto choose = [](SplatFormat f, bool b32, bool b16) { return liquid::choose_splat_format(f, b32, b16); };
  CHECK(choose(SplatFormat::Auto, true, true).format == VK_FORMAT_R32G32B32A32_SFLOAT);
  CHECK_FALSE(choose(SplatFormat::Auto, true, true).fell_back);
  CHECK(choose(SplatFormat::Auto, false, true).format == VK_FORMAT_R16G16B16A16_SFLOAT);
  CHECK(choose(SplatFormat::Auto, false, true).fell_back);
  CHECK(choose(SplatFormat::Rgba16f, true, true).format == VK_FORMAT_R16G16B16A16_SFLOAT);
  CHECK_FALSE(choose(SplatFormat::Rgba16f, true, true).fell_back);
  CHECK_THROWS_WITH(choose(SplatFormat::Rgba32f, false, true), Catch::Contains("RGBA32F"));
  CHECK_THROWS_WITH(choose(SplatFormat::Auto, false, false), Catch::Contains("RGBA32F or RGBA16F"));
}
