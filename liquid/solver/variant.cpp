#include "liquid/solver/variant.h"

#include "liquid/solver/mesh_field.h"

#include <algorithm>

namespace liquid {

uint32_t SolverVariant::shader_features() const {
  return (splat_adjoint() ? shader_feature::SPLAT_ADJOINT : 0u) | (meshes ? shader_feature::MESH_FIELD : 0u) |
         (layout.atlas() ? shader_feature::ATLAS : 0u) | (affine ? shader_feature::AFFINE : 0u) |
         (projection() ? shader_feature::PROJECTION : 0u);
}

std::string SolverVariant::description() const {
  std::string out = layout.dimension == 2 ? "2D" : "3D " + grid_path_description(layout.path);
  out += splat == SplatMode::Separable ? ", separable splat" : ", point-sprite splat";
  out += splat_adjoint() ? ", splat-adjoint pressure" : ", the chapter's pressure";
  if (meshes) out += ", meshes";
  if (bodies) out += ", bodies";
  if (active_region) out += ", active region";
  if (affine) out += ", affine transfer";
  if (position_correction) out += ", position correction";
  if (projection()) out += ", pressure projection (" + std::to_string(projection_iterations) + " iterations)";
  return out;
}

SolverVariant solver_variant(const Scene& scene, const SimulationSetup& setup, const GridLayout& layout,
                             bool active_region) {
  SolverVariant v;
  v.layout = layout;
  v.splat = setup.splat;
  v.pressure = setup.splat_adjoint_pressure ? PressureMode::SplatAdjoint : PressureMode::Chapter;
  v.meshes = has_mesh_obstacles(scene);
  v.bodies = std::any_of(scene.obstacles.begin(), scene.obstacles.end(), [](const Obstacle& o) { return o.dynamic; });
  v.active_region = active_region && layout.dimension == 3;
  v.affine = scene.transfer == Transfer::Affine;
  v.position_correction = scene.position_correction > 0.0f;
  v.projection_iterations = projection_iterations_of(scene);
  return v;
}

}  // namespace liquid
