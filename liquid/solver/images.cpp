#include "liquid/solver/images.h"

#include "liquid/solver/variant.h"

#include <stdexcept>
#include <string>

namespace liquid {
namespace {

void expect(ImageHandle image, bool needed, const char* name) {
  if (image.valid() == needed) return;
  throw std::logic_error(std::string("liquid: a step ") + (needed ? "without" : "with") + " the image " + name +
                         (needed ? ", which the solver's variant needs" : ", which the solver's variant has no use for"));
}

}  // namespace

void check_step_images(const StepImages& images, const SolverVariant& variant) {
  expect(images.particles.positions, true, "particles.positions");
  expect(images.particles.velocities, true, "particles.velocities");
  expect(images.particle_targets.positions, true, "particle_targets.positions");
  expect(images.particle_targets.velocities, true, "particle_targets.velocities");
  for (int i = 0; i < 3; ++i) {
    expect(images.particles.affine[size_t(i)], i < variant.affine_textures(), "particles.affine");
    expect(images.particle_targets.affine[size_t(i)], i < variant.affine_textures(), "particle_targets.affine");
  }
  expect(images.splat, true, "splat");
  expect(images.grids.velocity, true, "grids.velocity");
  expect(images.grids.density, true, "grids.density");
  expect(images.grids.correction, variant.projection(), "grids.correction");
  expect(images.bodies, true, "bodies");
  expect(images.body_targets, true, "body_targets");
  expect(images.body_shapes, true, "body_shapes");
  expect(images.mesh_field, variant.meshes, "mesh_field");
  expect(images.pressure.pressure, variant.splat_adjoint(), "pressure.pressure");
  expect(images.pressure.potential, variant.splat_adjoint(), "pressure.potential");
  expect(images.pressure.scratch, variant.pressure_scratch(), "pressure.scratch");
  expect(images.pressure.system, variant.projection(), "pressure.system");
}

}  // namespace liquid
