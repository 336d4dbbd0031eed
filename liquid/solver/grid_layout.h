// How the solver's 3D grids are stored and rendered into, chosen once per node from the device's
// features (2D scenes always use plain 2D images and need none of them):
//   GeometryShader  3D images; the full-screen grid passes reach each slice through the layered
//                   full-screen pair (its geometry shader writes gl_Layer), the splat through a small
//                   geometry shader of its own (splat.geom). Needs geometryShader.
//   VertexLayer     3D images; the vertex shaders write gl_Layer. Needs shaderOutputLayer.
//   Atlas           every 3D grid is one 2D image holding its slices side by side as tiles ("flat 3D
//                   texture"): only vertex and fragment shaders and 2D render targets, for devices
//                   with neither feature (MoltenVK, many mobile GPUs).
#pragma once

#include "engine/vk/image.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace liquid {

// The name and what the path needs, for the log: "vertex-layer (shaderOutputLayer)".
std::string grid_path_description(GridPath path);

// What the device offers for the layered paths.
struct GridPathSupport {
  bool geometry_shader = false;
  bool vertex_layer_output = false;
};
// `requested`, or (empty) the first the device supports of vertex-layer, geometry and atlas: the
// vertex-layer path draws the fewest primitives, and the atlas needs nothing. Throws
// DeviceError naming the missing feature when the requested path is not supported.
GridPath choose_grid_path(const GridPathSupport& support, std::optional<GridPath> requested);

// The storage of one grid of `cells` (z = 1 in 2D). In the atlas, slice z is the tile
// (z % tiles.x, z / tiles.x) of a (cells.x * tiles.x) x (cells.y * tiles.y) image, with
// tiles.x = ceil(sqrt(cells.z)) (near square, so neither side reaches the 2D limit long before the
// other) and tiles.y = ceil(cells.z / tiles.x); the tiles past the last slice are unused. Shaders get
// tiles through SolverUniforms::atlas_tiles (and the views' blocks for the occupancy grid) and map
// cells with shaders/liquid/grid_atlas.glsl.
struct GridLayout {
  GridLayout() = default;
  GridLayout(int dimension, glm::ivec3 cells, GridPath path);

  int dimension = 2;
  glm::ivec3 cells{1};
  GridPath path = GridPath::VertexLayer;
  glm::ivec2 tiles{1};  // (columns, rows) of slices; (1, 1) unless atlas()

  bool atlas() const { return dimension == 3 && path == GridPath::Atlas; }
  bool layered() const { return dimension == 3 && !atlas(); }
  // The image that holds the grid: 2D (a 2D scene or an atlas) or 3D.
  engine::vk::ImageDesc image_desc(VkFormat format, VkImageUsageFlags usage) const;
  // Index of cell (x, y, z)'s texel in the image's tightly packed download.
  size_t texel_index(int x, int y, int z) const;
  size_t cell_count() const { return size_t(cells.x) * cells.y * cells.z; }

  // A download of the image in the layout every caller reads: x fastest, then y, then z.
  template <class T>
  std::vector<T> to_linear(const std::vector<T>& image) const {
    if (!atlas()) return image;
    std::vector<T> out(cell_count());
    size_t i = 0;
    for (int z = 0; z < cells.z; ++z)
      for (int y = 0; y < cells.y; ++y)
        for (int x = 0; x < cells.x; ++x) out[i++] = image[texel_index(x, y, z)];
    return out;
  }
};

// The vertex (and geometry) shaders of a full-screen pass over every cell of a grid: one triangle
// over a 2D image or atlas, or one per slice routed by the path's layered pair; with
// `active_region` (3D only), each slice's rectangle of the step's active region instead
// (active_region.h).
struct GridPassShaders {
  std::span<const uint32_t> vertex;
  std::span<const uint32_t> geometry;  // empty but on the geometry-shader path
};
GridPassShaders grid_pass_shaders(const GridLayout& layout, bool active_region = false);

}  // namespace liquid
