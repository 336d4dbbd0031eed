#include "liquid/export/surface.h"

#include "liquid/error.h"
#include "liquid/export/vdb_file.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
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

// The cells within `reach` cells of the surface, and those of the layer of air around the domain
// beside them (indices -1 and n): where some cell of a cell's 3 x 3 x 3 neighbourhood (clamped to
// the domain) lies on the other side of the iso level, or a cell of liquid touches a wall.
std::vector<bool> cells_near_surface(const VolumeFrame& volume, float iso, int reach) {
  const glm::ivec3 n = volume.cells, padded = n + 2;
  const auto padded_index = [&](const glm::ivec3& c) {
    return size_t(c.x + 1) + size_t(padded.x) * (size_t(c.y + 1) + size_t(padded.y) * size_t(c.z + 1));
  };
  const auto liquid = [&](const glm::ivec3& c) { return volume.density[volume.index(c.x, c.y, c.z)] > iso; };
  std::vector<bool> near(size_t(padded.x) * padded.y * padded.z, false);
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) {
        const glm::ivec3 c(x, y, z);
        bool crossing = liquid(c) && (glm::any(glm::equal(c, glm::ivec3(0))) || glm::any(glm::equal(c, n - 1)));
        for (int i = 0; i < 27 && !crossing; ++i) {
          const glm::ivec3 other = glm::clamp(c + glm::ivec3(i % 3, i / 3 % 3, i / 9) - 1, glm::ivec3(0), n - 1);
          crossing = liquid(other) != liquid(c);
        }
        if (!crossing) continue;
        const glm::ivec3 lo = glm::max(c - reach, glm::ivec3(-1)), hi = glm::min(c + reach, n);
        for (int nz = lo.z; nz <= hi.z; ++nz)
          for (int ny = lo.y; ny <= hi.y; ++ny)
            for (int nx = lo.x; nx <= hi.x; ++nx) near[padded_index({nx, ny, nz})] = true;
      }
  return near;
}

// rho/rho0 at the voxel centres of the cells near the surface, as the raymarch samples it
// (density_at: trilinear, clamped to the outermost cell centres), and at one voxel outside the
// domain. There, beside a wall voxel of liquid, the wall voxel's value mirrored about the iso level,
// so the crossing between the two centres lies on the wall; air beside air, and at the box's edges
// and corners. Only those cells are active: the level set needs its band, not the whole domain.
openvdb::FloatGrid::Ptr density_near_surface(const VolumeFrame& volume, const SurfaceSettings& s,
                                             const openvdb::math::Transform::Ptr& transform) {
  const int k = s.voxels_per_cell;
  const glm::ivec3 cells = volume.cells, n = cells * k, padded = cells + 2;
  const float voxel = volume.cell_size / float(k);
  // The band's voxels, and the cells that decide them (the trilinear stencil reaches one cell).
  const int reach = int(std::ceil(k_surface_band_voxels / float(k))) + 1;
  const std::vector<bool> near = cells_near_surface(volume, s.iso_level, reach);
  const auto density = [&](const glm::ivec3& v) {
    return density_at(volume, volume.origin + (glm::vec3(v) + 0.5f) * voxel);
  };
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(transform);
  auto values = grid->getAccessor();
  for (int cz = -1; cz <= cells.z; ++cz)
    for (int cy = -1; cy <= cells.y; ++cy)
      for (int cx = -1; cx <= cells.x; ++cx) {
        if (!near[size_t(cx + 1) + size_t(padded.x) * (size_t(cy + 1) + size_t(padded.y) * size_t(cz + 1))]) continue;
        // The cell's voxels; a cell of the air layer has only the one layer of voxels beside the domain.
        const glm::ivec3 cell(cx, cy, cz);
        const glm::ivec3 lo = glm::max(cell * k, glm::ivec3(-1)), hi = glm::min(cell * k + k - 1, n);
        for (int z = lo.z; z <= hi.z; ++z)
          for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
              const glm::ivec3 v(x, y, z), wall = glm::clamp(v, glm::ivec3(0), n - 1);
              const int outside_axes = (v.x != wall.x) + (v.y != wall.y) + (v.z != wall.z);
              float value = 0.0f;
              if (outside_axes == 0) {
                value = density(v);
              } else if (outside_axes == 1) {
                const float inside = density(wall);
                if (inside > s.iso_level) value = 2.0f * s.iso_level - inside;
              }
              values.setValueOn(openvdb::Coord(x, y, z), value);
            }
      }
  return grid;
}

}  // namespace

LiquidSurface::LiquidSurface(const VolumeFrame& volume, const SurfaceSettings& settings)
    : level_set_(std::make_unique<LevelSet>()), settings_(settings), cell_size_(volume.cell_size) {
  check(volume, settings);
  initialize_openvdb_once();
  const openvdb::math::Transform::Ptr transform = voxel_centre_transform(volume.origin, voxel_size());
  // Distances solved from the density's crossings (fast sweeping), cut to the narrow band, and the
  // inactive voxels given the sign of the side they are on.
  const openvdb::FloatGrid::Ptr density = density_near_surface(volume, settings, transform);
  const float band = k_surface_band_voxels * float(voxel_size());
  level_set_->grid = density->empty() ? openvdb::FloatGrid::create(band)  // no liquid, or no air
                                      : openvdb::tools::fogToSdf(*density, settings.iso_level);
  level_set_->grid->setTransform(transform);
  openvdb::FloatTree& tree = level_set_->grid->tree();
  std::vector<openvdb::Coord> beyond;
  for (auto v = tree.cbeginValueOn(); v; ++v)
    if (!(std::abs(*v) <= band)) beyond.push_back(v.getCoord());
  for (const openvdb::Coord& c : beyond) tree.setValueOff(c, std::copysign(band, tree.getValue(c)));
  openvdb::tools::signedFloodFillWithValues(tree, band, -band);
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
