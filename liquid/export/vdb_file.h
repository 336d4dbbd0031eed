// What every OpenVDB file of a frame shares: the transform that puts voxel centres on cell centres,
// the frame's metadata, and a write that is atomic and gives identical bytes for identical grids.
#pragma once

#include "liquid/export/vdb.h"

#include <openvdb/openvdb.h>

#include <filesystem>

namespace liquid {

// OpenVDB's grid types must be registered once per process before any file is read or written.
void initialize_openvdb_once();

// Index (i, j, k) -> world in metres: voxel centre at origin + (i + 0.5, j + 0.5, k + 0.5) * voxel_size.
openvdb::math::Transform::Ptr voxel_centre_transform(const glm::vec3& origin, double voxel_size);

// The file's metadata: time_s, frame, cell_size_m, scene and (if set) fps.
openvdb::MetaMap frame_metadata(const VdbFrame& frame, double cell_size);

// Writes `grids` through a temporary name renamed into place, with a UUID made from the content;
// throws liquid::Error naming the path when it cannot be written.
void write_vdb_grids(const std::filesystem::path& path, const openvdb::GridPtrVec& grids, const openvdb::MetaMap& meta);

}  // namespace liquid
