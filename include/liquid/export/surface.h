// The liquid's surface of a frame (built only where OpenVDB is installed: RASTERLIQUIDS_HAVE_OPENVDB):
// a narrow-band level set of the density grid's isosurface, the one the raymarch draws, and the
// triangle mesh of its zero crossing. The surface closes against the domain's walls and floor as
// the raymarch draws it: its sampler clamps the density to the outermost cell centres up to the
// walls, so liquid whose wall voxel is above the iso level reaches the wall, and the box ends there.
// The density is padded by one voxel outside the domain whose value puts the crossing on the wall
// (air beside a wall voxel of air).
#pragma once

#include "liquid/export/mesh_file.h"
#include "liquid/export/vdb.h"
#include "liquid/export/volume.h"
#include "liquid/types.h"

#include <filesystem>
#include <memory>

namespace liquid {

// The level set's narrow band, in voxels each side of the surface.
inline constexpr float k_surface_band_voxels = 3.0f;
// Surface voxels per cell edge: from 1 (the grid's own detail) to 8 (512 voxels a cell already
// cost more than the frame's simulation). A whole number, so voxel faces meet the walls.
inline constexpr int k_max_surface_voxels_per_cell = 8;

struct SurfaceSettings {
  float iso_level = k_default_iso_level;  // rho/rho0 at the surface, as the raymarch draws it by default
  // Voxels of half a cell by default: the raymarch draws the trilinear density's crossing, which
  // curves between cell centres; at one voxel a cell the mesh would have one vertex a cell, facets a
  // cell wide, for an eighth of the voxels (the export's time in docs/caches.md).
  int voxels_per_cell = 2;
  float adaptivity = 0.0f;  // volumeToMesh's, 0 to 1: 0 keeps every voxel's polygon, more merges flat regions
};

class LiquidSurface {
 public:
  // Throws ArgumentError for settings out of range and a 2D (one cell deep) volume.
  LiquidSurface(const VolumeFrame& volume, const SurfaceSettings& settings);
  ~LiquidSurface();
  LiquidSurface(const LiquidSurface&) = delete;
  LiquidSurface& operator=(const LiquidSurface&) = delete;

  double voxel_size() const;  // m
  // The level set trilinearly interpolated at `world` (m): signed distance to the surface, negative
  // inside; +-k_surface_band_voxels voxels outside the band.
  float signed_distance(const glm::vec3& world) const;
  // The zero crossing as triangles (quads split in two), wound outward, with each vertex's velocity
  // sampled from `volume` (sample_velocity).
  SurfaceMesh mesh(const VolumeFrame& volume) const;
  // An OpenVDB file with one level-set grid, "surface" (signed distance in m, negative inside), its
  // voxel centres at origin + (i + 0.5) * voxel_size like the density grid's; metadata as write_vdb's,
  // and the grid's iso_level and time_s. Throws liquid::Error naming the path when it cannot be written.
  void write_vdb(const std::filesystem::path& path, const VdbFrame& frame) const;

 private:
  struct LevelSet;
  std::unique_ptr<LevelSet> level_set_;
  SurfaceSettings settings_;
  float cell_size_ = 0.0f;
};

}  // namespace liquid
