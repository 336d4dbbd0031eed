#include "liquid/solver/grid_layout.h"

#include "engine/passes/fullscreen.h"
#include "liquid_shader_families.h"

#include <iterator>
#include <stdexcept>

namespace liquid {

const char* grid_path_name(GridPath path) {
  switch (path) {
    case GridPath::GeometryShader: return "geometry";
    case GridPath::VertexLayer: return "vertex-layer";
    case GridPath::Atlas: return "atlas";
  }
  return "?";
}

std::string grid_path_description(GridPath path) {
  switch (path) {
    case GridPath::GeometryShader: return "geometry (geometryShader)";
    case GridPath::VertexLayer: return "vertex-layer (shaderOutputLayer)";
    case GridPath::Atlas: return "atlas (2D tiles of the slices; vertex and fragment shaders only)";
  }
  return "?";
}

std::string grid_path_names(std::string_view separator, std::string_view last_separator) {
  constexpr size_t count = std::size(k_grid_paths);
  std::string names;
  for (size_t i = 0; i < count; ++i) {
    if (i > 0) names += i + 1 == count ? last_separator : separator;
    names += grid_path_name(k_grid_paths[i]);
  }
  return names;
}

std::optional<GridPath> find_grid_path(std::string_view name) {
  for (GridPath path : k_grid_paths)
    if (name == grid_path_name(path)) return path;
  return std::nullopt;
}

std::string not_a_grid_path(std::string_view text) {
  return "'" + std::string(text) + "' is not a 3D path (" + grid_path_names(", ", " or ") + ")";
}

GridPath parse_grid_path(std::string_view text, std::string_view where) {
  if (const std::optional<GridPath> path = find_grid_path(text)) return *path;
  throw ArgumentError(std::string(where) + ": " + not_a_grid_path(text));
}

GridPath choose_grid_path(const GridPathSupport& support, std::optional<GridPath> requested) {
  if (!requested) {
    if (support.vertex_layer_output) return GridPath::VertexLayer;
    if (support.geometry_shader) return GridPath::GeometryShader;
    return GridPath::Atlas;
  }
  if (*requested == GridPath::GeometryShader && !support.geometry_shader)
    throw DeviceError("the 3D path 'geometry' needs the device feature geometryShader, which is not enabled");
  if (*requested == GridPath::VertexLayer && !support.vertex_layer_output)
    throw DeviceError("the 3D path 'vertex-layer' needs the device feature shaderOutputLayer "
                      "(gl_Layer from vertex shaders), which is not enabled");
  return *requested;
}

GridLayout::GridLayout(int dimension_, glm::ivec3 cells_, GridPath path_)
    : dimension(dimension_), cells(dimension_ == 3 ? cells_ : glm::ivec3(cells_.x, cells_.y, 1)), path(path_) {
  if (atlas()) {
    int columns = 1;  // ceil(sqrt(nz)) in integers
    while (columns * columns < cells.z) ++columns;
    tiles = {columns, (cells.z + columns - 1) / columns};
  }
}

engine::vk::ImageDesc GridLayout::image_desc(VkFormat format, VkImageUsageFlags usage) const {
  using engine::vk::ImageKind;
  if (layered()) return {ImageKind::Image3D, uint32_t(cells.x), uint32_t(cells.y), uint32_t(cells.z), format, usage};
  return {ImageKind::Image2D, uint32_t(cells.x * tiles.x), uint32_t(cells.y * tiles.y), 1, format, usage};
}

size_t GridLayout::texel_index(int x, int y, int z) const {
  if (!atlas()) return size_t(x) + size_t(cells.x) * (size_t(y) + size_t(cells.y) * z);
  const size_t ax = size_t(x) + size_t(z % tiles.x) * cells.x;
  const size_t ay = size_t(y) + size_t(z / tiles.x) * cells.y;
  return ax + ay * size_t(cells.x) * tiles.x;
}

GridPassShaders grid_pass_shaders(const GridLayout& layout, bool active_region) {
  if (active_region) {
    const std::span<const uint32_t> vertex = shader_variant(liquid::shaders::active_region_vert, layout);
    if (layout.path == GridPath::GeometryShader && layout.layered())
      return {vertex, engine::passes::fullscreen_layered_geometry_shader()};
    return {vertex, {}};
  }
  if (!layout.layered()) return {engine::passes::fullscreen_vertex_shader(), {}};
  if (layout.path == GridPath::GeometryShader)
    return {engine::passes::fullscreen_layered_vertex_shader(), engine::passes::fullscreen_layered_geometry_shader()};
  return {engine::passes::fullscreen_vertex_layer_shader(), {}};
}

}  // namespace liquid
