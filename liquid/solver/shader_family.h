// A shader's variants, compiled at build time from one GLSL source (cmake/ShaderFamilies.cmake,
// listed in liquid/CMakeLists.txt): one per grid layout the shader has code for, times every
// subset of its features. The generated liquid_shader_families.h declares each family as
// liquid::shaders::<name>; a pass takes its variant with shader_variant(), never by a name.
#pragma once

#include "liquid/solver/grid_layout.h"

#include <cstdint>
#include <span>

namespace liquid {

// The layouts a variant is compiled for (the DIM, ATLAS, VERTEX_LAYER and GEOMETRY_LAYER defines).
enum class ShaderLayout : uint8_t {
  Any,                // one compile for every layout
  TwoD,               // a 2D grid
  ThreeD,             // a 3D grid on a layered path (unless the family has that path's own)
  ThreeDAll,          // a 3D grid on any path
  ThreeDVertexLayer,  // GridPath::VertexLayer
  ThreeDGeometry,     // GridPath::GeometryShader
  ThreeDAtlas,        // GridPath::Atlas
};

// The features a variant may be compiled with: each the GLSL define of its name, set to 1.
namespace shader_feature {
constexpr uint32_t SPLAT_ADJOINT = 1u << 0;  // the grid pass takes the potential's gradient
constexpr uint32_t MESH_FIELD = 1u << 1;     // the pass samples the static meshes' field
constexpr uint32_t ATLAS = 1u << 2;          // the grid is an atlas, for a shader without layouts of its own
constexpr uint32_t TRANSMIT = 1u << 3;       // the raymarch writes the liquid's transmittance
constexpr uint32_t AFFINE = 1u << 4;         // the affine transfer: the particles carry C_p
constexpr uint32_t PROJECTION = 1u << 5;     // the grid pass takes the pressure projection's gradient
}  // namespace shader_feature

struct ShaderFamily {
  const char* name;
  std::span<const ShaderLayout> layouts;
  std::span<const uint32_t> features;  // the feature of each bit of a subset's index
  // variants[l * 2^features.size() + s]: layout l with the features of subset s's bits.
  std::span<const std::span<const uint32_t>> variants;
};

// The variant of `family` for a grid of `layout` with the `features` it has (those of the family's
// features that are set; others are ignored). std::logic_error when the family has no code for the
// layout.
std::span<const uint32_t> shader_variant(const ShaderFamily& family, const GridLayout& layout, uint32_t features = 0);
// A family compiled for every layout (ShaderLayout::Any).
std::span<const uint32_t> shader_variant(const ShaderFamily& family, uint32_t features = 0);

}  // namespace liquid
