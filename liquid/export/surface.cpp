#include "liquid/export/surface.h"

#include "liquid/error.h"
#include "liquid/export/vdb_file.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <string>
#include <vector>

namespace liquid {

struct LiquidSurface::LevelSet {
  openvdb::FloatGrid::Ptr grid;
};

namespace {

void check(const VolumeFrame& volume, const SurfaceSettings& s) {
  if (volume.cells.z < 2) throw ArgumentError("surface: needs a 3D volume, got one cell deep");
  if (s.voxels_per_cell < 1 || s.voxels_per_cell > k_max_surface_voxels_per_cell)
    throw ArgumentError("surface: " + std::to_string(s.voxels_per_cell) + " voxels a cell is outside [1, " +
                        std::to_string(k_max_surface_voxels_per_cell) + "]");
  if (!(s.adaptivity >= 0.0f && s.adaptivity <= 1.0f))
    throw ArgumentError("surface: adaptivity " + std::to_string(s.adaptivity) + " is outside [0, 1]");
  if (!(s.iso_level > 0.0f && std::isfinite(s.iso_level)))
    throw ArgumentError("surface: iso level " + std::to_string(s.iso_level) + " is not a positive density ratio");
}

// rho/rho0 at every voxel centre of the domain, as the raymarch samples it (sample_density: trilinear, clamped to the outermost cell
// centres), and one voxel outside. There, beside a wall voxel of liquid, the wall voxel's value
// mirrored about the iso level, so the crossing between the two centres lies on the wall; air
// beside air, and at the box's edges and corners.
openvdb::FloatGrid::Ptr padded_density(const VolumeFrame& volume, const SurfaceSettings& s,
                                                const openvdb::math::Transform::Ptr& transform) {
  const glm::ivec3 n = volume.cells * s.voxels_per_cell;
  const float voxel = volume.cell_size / float(s.voxels_per_cell);
  std::vector<glm::vec4> centres;
  centres.reserve(size_t(n.x) * n.y * n.z);
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) centres.emplace_back(volume.origin + (glm::vec3(x, y, z) + 0.5f) * voxel, 1.0f);
  const std::vector<float> rho = sample_density(volume, centres);
  const auto inside_value = [&](const glm::ivec3& c) { return rho[size_t(c.x) + size_t(n.x) * (size_t(c.y) + size_t(n.y) * c.z)]; };

  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(transform);
  auto values = grid->getAccessor();
  for (int z = -1; z <= n.z; ++z)
    for (int y = -1; y <= n.y; ++y)
      for (int x = -1; x <= n.x; ++x) {
        const glm::ivec3 c(x, y, z), wall = glm::clamp(c, glm::ivec3(0), n - 1);
        const int outside_axes = (c.x != wall.x) + (c.y != wall.y) + (c.z != wall.z);
        float value = 0.0f;
        if (outside_axes == 0) {
          value = inside_value(c);
        } else if (outside_axes == 1 && inside_value(wall) > s.iso_level) {
          value = 2.0f * s.iso_level - inside_value(wall);
        }
        values.setValueOn(openvdb::Coord(x, y, z), value);
      }
  return grid;
}

}  // namespace

LiquidSurface::LiquidSurface(const VolumeFrame& volume, const SurfaceSettings& settings)
    : level_set_(std::make_unique<LevelSet>()), settings_(settings), cell_size_(volume.cell_size) {
  check(volume, settings);
  initialize_openvdb_once();
  const openvdb::math::Transform::Ptr transform = voxel_centre_transform(volume.origin, voxel_size());
  // Distances solved from the density's crossings (fast sweeping), then cut to the narrow band.
  const openvdb::FloatGrid::Ptr density = padded_density(volume, settings, transform);
  level_set_->grid = openvdb::tools::fogToSdf(*density, settings.iso_level);
  const float band = k_surface_band_voxels * float(voxel_size());
  openvdb::FloatTree& tree = level_set_->grid->tree();
  std::vector<openvdb::Coord> beyond;
  for (auto v = tree.cbeginValueOn(); v; ++v)
    if (std::abs(*v) > band) beyond.push_back(v.getCoord());
  for (const openvdb::Coord& c : beyond) tree.setValueOff(c, std::copysign(band, tree.getValue(c)));
  openvdb::tools::changeLevelSetBackground(tree, band);
  openvdb::tools::pruneLevelSet(tree);
  level_set_->grid->setName("surface");
  level_set_->grid->setGridClass(openvdb::GRID_LEVEL_SET);
  level_set_->grid->insertMeta("iso_level", openvdb::FloatMetadata(settings.iso_level));
}

LiquidSurface::~LiquidSurface() = default;

double LiquidSurface::voxel_size() const { return double(cell_size_) / settings_.voxels_per_cell; }

float LiquidSurface::signed_distance(const glm::vec3& world) const {
  const openvdb::FloatGrid& grid = *level_set_->grid;
  const openvdb::Vec3d index = grid.worldToIndex(openvdb::Vec3d(world.x, world.y, world.z));
  return openvdb::tools::BoxSampler::sample(grid.tree(), index);
}

SurfaceMesh LiquidSurface::mesh(const VolumeFrame& volume) const {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*level_set_->grid, points, triangles, quads, 0.0, settings_.adaptivity);
  SurfaceMesh mesh;
  mesh.positions.reserve(points.size());
  for (const openvdb::Vec3s& p : points) mesh.positions.emplace_back(p.x(), p.y(), p.z());
  // volumeToMesh winds a level set's polygons clockwise seen from outside: reversed here.
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const openvdb::Vec3I& t : triangles) mesh.triangles.emplace_back(t[2], t[1], t[0]);
  for (const openvdb::Vec4I& q : quads) {
    mesh.triangles.emplace_back(q[2], q[1], q[0]);
    mesh.triangles.emplace_back(q[3], q[2], q[0]);
  }
  mesh.velocities = sample_velocity(volume, mesh.positions);
  return mesh;
}

void LiquidSurface::write_vdb(const std::filesystem::path& path, const VdbFrame& frame) const {
  openvdb::FloatGrid::Ptr grid = level_set_->grid;
  grid->insertMeta("time_s", openvdb::DoubleMetadata(frame.time_s));
  write_vdb_grids(path, {grid}, frame_metadata(frame, cell_size_));
}

}  // namespace liquid
