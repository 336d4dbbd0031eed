// OpenVDB volumes of a frame (built only where OpenVDB is installed: RASTERLIQUIDS_HAVE_OPENVDB). Two
// grids: float "density" (rho/rho0, a fog volume) and vec3 "velocity" (m/s), active only where the
// cell holds liquid (rho/rho0 at least k_vdb_min_density; velocity only where density is active),
// and with whitewater (VolumeFrame::foam) a third, float "foam" (foam particles per m^3), active
// where it is above 0; all with one world transform in metres: voxel (i, j, k) is the cell whose
// centre is origin + (i + 0.5, j + 0.5, k + 0.5) * cell_size. 2D grids become one voxel deep (k = 0).
// Identical frames give byte-identical files: the file's UUID is made from its content.
#pragma once

#include "liquid/export/volume.h"

#include <filesystem>
#include <string>
#include <vector>

namespace liquid {

// The kernel's tail leaves densities down to 1e-7 rho0 a few cells past the surface, which would
// make most of the bounding box active (80 % of small_3d's); a thousandth of rho0 is far below
// anything a fog shader or a surface at isovalue 0.5 shows.
inline constexpr float k_vdb_min_density = 1e-3f;

struct VdbFrame {
  int frame = 0;
  double time_s = 0.0;  // simulated time, stored in the file's metadata as "time_s"
  std::string scene;    // stored as "scene"
  double fps = 0.0;     // frames per simulated second of the sequence, stored as "fps" (0: not stored)
};

// Writes the file through a temporary name renamed into place; throws liquid::Error naming
// the path when it cannot be written, ArgumentError when volume.foam is neither empty nor one value
// a cell.
void write_vdb(const std::filesystem::path& path, const VolumeFrame& volume, const VdbFrame& frame);

// A file read back through OpenVDB: its grids' active voxels and what places them, for checking
// a written file against the node's readback.
struct VdbContents {
  template <class T>
  struct Voxel {
    glm::ivec3 index;
    T value;
  };
  std::vector<std::string> grid_names;
  VdbFrame frame;
  double voxel_size = 0.0;      // m
  glm::dvec3 voxel_zero{0.0};   // world position of voxel (0, 0, 0), m
  std::vector<Voxel<float>> density;
  std::vector<Voxel<glm::vec3>> velocity;
  std::vector<Voxel<float>> foam;  // empty when the file has no foam grid
};
// Throws liquid::Error naming the path when it cannot be read or lacks the density or velocity grid.
VdbContents read_vdb(const std::filesystem::path& path);

}  // namespace liquid
