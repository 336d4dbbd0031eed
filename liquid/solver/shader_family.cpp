#include "liquid/solver/shader_family.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace liquid {
namespace {

// The layouts that hold code for `layout`, best first (Any: none found).
std::array<ShaderLayout, 4> candidates(const GridLayout& layout) {
  using L = ShaderLayout;
  if (layout.dimension == 2) return {L::TwoD, L::Any, L::Any, L::Any};
  switch (layout.path) {
    case GridPath::Atlas: return {L::ThreeDAtlas, L::ThreeDAll, L::Any, L::Any};
    case GridPath::GeometryShader: return {L::ThreeDGeometry, L::ThreeD, L::ThreeDAll, L::Any};
    case GridPath::VertexLayer: break;
  }
  return {L::ThreeDVertexLayer, L::ThreeD, L::ThreeDAll, L::Any};
}

std::span<const uint32_t> variant_at(const ShaderFamily& family, size_t layout_index, uint32_t features) {
  size_t subset = 0;
  for (size_t bit = 0; bit < family.features.size(); ++bit)
    if (features & family.features[bit]) subset |= size_t(1) << bit;
  return family.variants[(layout_index << family.features.size()) + subset];
}

}  // namespace

std::span<const uint32_t> shader_variant(const ShaderFamily& family, const GridLayout& layout, uint32_t features) {
  for (ShaderLayout wanted : candidates(layout)) {
    const auto found = std::find(family.layouts.begin(), family.layouts.end(), wanted);
    if (found != family.layouts.end()) return variant_at(family, size_t(found - family.layouts.begin()), features);
  }
  throw std::logic_error(std::string("liquid: shader ") + family.name + " has no variant for a " +
                         std::to_string(layout.dimension) + "D grid on this path");
}

std::span<const uint32_t> shader_variant(const ShaderFamily& family, uint32_t features) {
  if (family.layouts.size() != 1 || family.layouts[0] != ShaderLayout::Any)
    throw std::logic_error(std::string("liquid: shader ") + family.name + " has a variant per grid layout");
  return variant_at(family, 0, features);
}

}  // namespace liquid
