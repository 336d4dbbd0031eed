// The solver's modes as one value, computed once per node from the scene, its setup and the device:
// the grid's layout (2D, or 3D on one of liquid/solver/grid_layout.h's paths), the splat, the
// pressure, and which optional images a step has (the static meshes' field, the dynamic bodies, the
// active region). Every pass takes its shader variant and its bindings from it, and a step's images
// (liquid/solver/images.h) are checked against it once per frame.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/shader_family.h"

#include <cstdint>
#include <span>
#include <string>

namespace liquid {

// How the grid pass gets its pressure force: the gradient of the cells' P (the chapter's,
// eq. 4) or of its smoothing by the splat's kernel (the splat-adjoint pressure, pressure.h).
enum class PressureMode : uint8_t { Chapter, SplatAdjoint };

struct SolverVariant {
  GridLayout layout;                              // dimension, cells and the 3D path
  SplatMode splat = SplatMode::PointSprite;       // the chapter's point sprites, or separable
  PressureMode pressure = PressureMode::Chapter;
  bool meshes = false;         // static mesh obstacles: the grid, pressure and particle passes sample their field
  bool bodies = false;         // dynamic obstacles: the body force and integration passes run
  bool active_region = false;  // 3D: the grid passes draw the step's active region only
  bool affine = false;         // the affine transfer: the particles carry C_p (affine_textures() of them)
  bool position_correction = false;  // the particle pass pushes particles out of over-packed cells
  int projection_iterations = 0;     // > 0: the pressure is a projection's, by this many Jacobi passes

  bool splat_adjoint() const { return pressure == PressureMode::SplatAdjoint; }
  bool projection() const { return projection_iterations > 0; }
  // The splat-adjoint pressure needs a third grid when bodies read P after the separable spread,
  // which otherwise alternates between P's image and Phi's (PressureImages::scratch).
  bool pressure_scratch() const { return splat_adjoint() && bodies && splat == SplatMode::Separable; }
  // The particle textures of C_p under the affine transfer: its columns d u / d x_a, packed into one
  // texture in 2D (xy the x column, zw the y column), one per axis in 3D; none otherwise.
  int affine_textures() const { return affine ? (layout.dimension == 2 ? 1 : 3) : 0; }
  // The shader_feature bits of the variant (SPLAT_ADJOINT, MESH_FIELD, ATLAS, AFFINE).
  uint32_t shader_features() const;
  // A solver shader for this variant: the family's code for the layout, with the features it has.
  std::span<const uint32_t> shader(const ShaderFamily& family) const {
    return shader_variant(family, layout, shader_features());
  }
  // "3D vertex-layer, separable splat, splat-adjoint pressure, meshes, bodies, active region": for logs.
  std::string description() const;
};

// The vertex (and geometry) shaders of a full-screen pass over the variant's grid: every cell, or
// the step's active region (liquid/solver/grid_layout.h).
inline GridPassShaders grid_pass_shaders(const SolverVariant& variant) {
  return grid_pass_shaders(variant.layout, variant.active_region);
}

// `layout` is the grid's (the device picks the 3D path); `active_region` is the host's option
// (LiquidOptions::active_region), which only 3D grids take.
SolverVariant solver_variant(const Scene& scene, const SimulationSetup& setup, const GridLayout& layout,
                             bool active_region);

}  // namespace liquid
