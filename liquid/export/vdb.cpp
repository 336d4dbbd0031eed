#include "liquid/export/vdb.h"

#include <openvdb/openvdb.h>

#include <mutex>
#include <stdexcept>
#include <system_error>

namespace liquid {
namespace {

// OpenVDB's grid types must be registered once per process before any file is read or written.
void initialize_once() {
  static std::once_flag initialized;
  std::call_once(initialized, [] { openvdb::initialize(); });
}

}  // namespace

void write_vdb(const std::filesystem::path& path, const VolumeFrame& volume, const VdbFrame& frame) {
  initialize_once();

  // Index (i, j, k) -> world: scale by the cell size, then shift by half a cell, so voxel centres
  // land on cell centres (OpenVDB puts a voxel's value at its integer coordinate).
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(volume.cell_size);
  transform->postTranslate(openvdb::Vec3d(volume.origin.x, volume.origin.y, volume.origin.z) +
                           openvdb::Vec3d(0.5 * volume.cell_size));

  openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
  density->setName("density");
  density->setGridClass(openvdb::GRID_FOG_VOLUME);
  density->setTransform(transform);
  openvdb::Vec3SGrid::Ptr velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  velocity->setName("velocity");
  velocity->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);  // a world-space direction per voxel
  velocity->setTransform(transform);

  auto rho = density->getAccessor();
  auto u = velocity->getAccessor();
  for (int z = 0; z < volume.cells.z; ++z)
    for (int y = 0; y < volume.cells.y; ++y)
      for (int x = 0; x < volume.cells.x; ++x) {
        const size_t i = volume.index(x, y, z);
        const openvdb::Coord c(x, y, z);
        if (volume.density[i] > 0.0f) rho.setValue(c, volume.density[i]);
        const glm::vec4& v = volume.velocity[i];
        if (v.w >= 0.5f) u.setValue(c, openvdb::Vec3s(v.x, v.y, v.z));
      }

  openvdb::MetaMap meta;
  meta.insertMeta("time_s", openvdb::DoubleMetadata(frame.time_s));
  meta.insertMeta("frame", openvdb::Int32Metadata(frame.frame));
  meta.insertMeta("cell_size_m", openvdb::DoubleMetadata(volume.cell_size));
  meta.insertMeta("scene", openvdb::StringMetadata(frame.scene));
  if (frame.fps > 0.0) meta.insertMeta("fps", openvdb::DoubleMetadata(frame.fps));
  for (openvdb::GridBase* grid : {static_cast<openvdb::GridBase*>(density.get()), static_cast<openvdb::GridBase*>(velocity.get())})
    grid->insertMeta("time_s", openvdb::DoubleMetadata(frame.time_s));

  std::filesystem::path temporary = path;
  temporary += ".partial";
  try {
    openvdb::io::File file(temporary.string());
    file.write({density, velocity}, meta);
    file.close();
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(path.string() + ": cannot write (" + e.what() + ")");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(path.string() + ": cannot rename into place");
  }
}

VdbContents read_vdb(const std::filesystem::path& path) {
  initialize_once();
  VdbContents out;
  try {
    openvdb::io::File file(path.string());
    file.open();
    const openvdb::MetaMap::Ptr meta = file.getMetadata();
    out.frame.time_s = meta->metaValue<double>("time_s");
    out.frame.frame = meta->metaValue<int32_t>("frame");
    out.frame.scene = meta->metaValue<std::string>("scene");
    for (auto name = file.beginName(); name != file.endName(); ++name) out.grid_names.push_back(name.gridName());
    const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    const auto velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("velocity"));
    file.close();
    if (!density || !velocity) throw std::runtime_error(path.string() + ": the density or velocity grid has the wrong type");
    out.voxel_size = density->voxelSize()[0];
    const openvdb::Vec3d zero = density->indexToWorld(openvdb::Vec3d(0.0));
    out.voxel_zero = {zero.x(), zero.y(), zero.z()};
    for (auto v = density->cbeginValueOn(); v; ++v)
      out.density.push_back({{v.getCoord().x(), v.getCoord().y(), v.getCoord().z()}, *v});
    for (auto v = velocity->cbeginValueOn(); v; ++v)
      out.velocity.push_back({{v.getCoord().x(), v.getCoord().y(), v.getCoord().z()}, {(*v).x(), (*v).y(), (*v).z()}});
  } catch (const openvdb::Exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
  return out;
}

}  // namespace liquid
