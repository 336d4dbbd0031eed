#include "liquid/export/vdb.h"

#include "liquid/error.h"
#include "liquid/export/vdb_file.h"

#include <openvdb/openvdb.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <system_error>

namespace liquid {
namespace {

// OpenVDB writes a random UUID into every file's header (Archive::writeHeader: the magic number,
// three version numbers and a grid-offsets flag, 21 bytes, then the UUID as 36 characters), so two
// identical runs would give files that differ in it. Replace it by one hashed from the rest of the
// file (two FNV-1a 64 hashes, as an RFC 9562 version 8 UUID): equal content, equal files.
constexpr std::streamoff k_uuid_offset = 21;
constexpr size_t k_uuid_length = 36;

bool looks_like_uuid(const std::string& text) {
  if (text.size() != k_uuid_length) return false;
  for (size_t i = 0; i < text.size(); ++i) {
    const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
    if (dash ? text[i] != '-' : !std::isxdigit(static_cast<unsigned char>(text[i]))) return false;
  }
  return true;
}

void stamp_content_uuid(const std::filesystem::path& path) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file.good() && !file.eof()) throw liquid::Error("cannot read the file back");
  if (bytes.size() < k_uuid_offset + k_uuid_length || !looks_like_uuid(bytes.substr(k_uuid_offset, k_uuid_length)))
    throw std::logic_error("the OpenVDB header has no UUID where this build expects it");
  std::array<uint64_t, 2> hash{0xcbf29ce484222325ull, 0x84222325cbf29ce4ull};
  for (size_t i = k_uuid_offset + k_uuid_length; i < bytes.size(); ++i)
    for (uint64_t& h : hash) h = (h ^ static_cast<unsigned char>(bytes[i])) * 0x100000001b3ull;
  hash[0] = (hash[0] & ~0xf000ull) | 0x8000ull;                                 // version 8
  hash[1] = (hash[1] & 0x3fffffffffffffffull) | 0x8000000000000000ull;          // variant 10
  char uuid[k_uuid_length + 1];
  std::snprintf(uuid, sizeof uuid, "%08x-%04x-%04x-%04x-%012llx", unsigned(hash[0] >> 32),
                unsigned(hash[0] >> 16 & 0xffff), unsigned(hash[0] & 0xffff), unsigned(hash[1] >> 48),
                static_cast<unsigned long long>(hash[1] & 0xffffffffffffull));
  file.clear();
  file.seekp(k_uuid_offset);
  file.write(uuid, k_uuid_length);
  file.close();
  if (!file) throw liquid::Error("cannot write the file's UUID");
}

}  // namespace

void initialize_openvdb_once() {
  static std::once_flag initialized;
  std::call_once(initialized, [] { openvdb::initialize(); });
}

openvdb::math::Transform::Ptr voxel_centre_transform(const glm::vec3& origin, double voxel_size) {
  // Scale by the voxel size, then shift by half a voxel, so voxel centres land where cells' centres
  // are (OpenVDB puts a voxel's value at its integer coordinate).
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(voxel_size);
  transform->postTranslate(openvdb::Vec3d(origin.x, origin.y, origin.z) + openvdb::Vec3d(0.5 * voxel_size));
  return transform;
}

openvdb::MetaMap frame_metadata(const VdbFrame& frame, double cell_size) {
  openvdb::MetaMap meta;
  meta.insertMeta("time_s", openvdb::DoubleMetadata(frame.time_s));
  meta.insertMeta("frame", openvdb::Int32Metadata(frame.frame));
  meta.insertMeta("cell_size_m", openvdb::DoubleMetadata(cell_size));
  meta.insertMeta("scene", openvdb::StringMetadata(frame.scene));
  if (frame.fps > 0.0) meta.insertMeta("fps", openvdb::DoubleMetadata(frame.fps));
  return meta;
}

void write_vdb_grids(const std::filesystem::path& path, const openvdb::GridPtrVec& grids, const openvdb::MetaMap& meta) {
  std::filesystem::path temporary = path;
  temporary += ".partial";
  try {
    openvdb::io::File file(temporary.string());
    file.write(grids, meta);
    file.close();
    stamp_content_uuid(temporary);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw liquid::Error(path.string() + ": cannot write (" + e.what() + ")");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw liquid::Error(path.string() + ": cannot rename into place");
  }
}

void write_vdb(const std::filesystem::path& path, const VolumeFrame& volume, const VdbFrame& frame) {
  initialize_openvdb_once();
  const openvdb::math::Transform::Ptr transform = voxel_centre_transform(volume.origin, volume.cell_size);

  openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
  density->setName("density");
  density->setGridClass(openvdb::GRID_FOG_VOLUME);
  density->setTransform(transform);
  openvdb::Vec3SGrid::Ptr velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  velocity->setName("velocity");
  velocity->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);  // a world-space direction per voxel
  velocity->setTransform(transform);

  openvdb::GridPtrVec grids{density, velocity};
  // With whitewater: a number density, not a fog volume's 0 to 1, so the grid's class stays unknown.
  openvdb::FloatGrid::Ptr foam;
  if (!volume.foam.empty()) {
    if (volume.foam.size() != volume.density.size())
      throw ArgumentError("write_vdb: " + std::to_string(volume.foam.size()) + " foam values for " +
                          std::to_string(volume.density.size()) + " cells");
    foam = openvdb::FloatGrid::create(0.0f);
    foam->setName("foam");
    foam->setTransform(transform);
    foam->insertMeta("unit", openvdb::StringMetadata("particles per m^3"));
    grids.push_back(foam);
  }

  auto rho = density->getAccessor();
  auto u = velocity->getAccessor();
  for (int z = 0; z < volume.cells.z; ++z)
    for (int y = 0; y < volume.cells.y; ++y)
      for (int x = 0; x < volume.cells.x; ++x) {
        const size_t i = volume.index(x, y, z);
        const openvdb::Coord c(x, y, z);
        if (foam && volume.foam[i] > 0.0f) foam->tree().setValue(c, volume.foam[i]);
        if (!(volume.density[i] >= k_vdb_min_density)) continue;  // velocity too: none without liquid
        rho.setValue(c, volume.density[i]);
        const glm::vec4& v = volume.velocity[i];
        if (v.w >= 0.5f) u.setValue(c, openvdb::Vec3s(v.x, v.y, v.z));
      }

  for (const openvdb::GridBase::Ptr& grid : grids) grid->insertMeta("time_s", openvdb::DoubleMetadata(frame.time_s));
  write_vdb_grids(path, grids, frame_metadata(frame, volume.cell_size));
}

VdbContents read_vdb(const std::filesystem::path& path) {
  initialize_openvdb_once();
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
    const bool has_foam = file.hasGrid("foam");
    const auto foam = has_foam ? openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("foam")) : nullptr;
    file.close();
    if (!density || !velocity || (has_foam && !foam))
      throw liquid::Error(path.string() + ": the density, velocity or foam grid has the wrong type");
    out.voxel_size = density->voxelSize()[0];
    const openvdb::Vec3d zero = density->indexToWorld(openvdb::Vec3d(0.0));
    out.voxel_zero = {zero.x(), zero.y(), zero.z()};
    const auto index = [](const openvdb::Coord& c) { return glm::ivec3(c.x(), c.y(), c.z()); };
    for (auto v = density->cbeginValueOn(); v; ++v) out.density.push_back({index(v.getCoord()), *v});
    for (auto v = velocity->cbeginValueOn(); v; ++v)
      out.velocity.push_back({index(v.getCoord()), {(*v).x(), (*v).y(), (*v).z()}});
    if (foam)
      for (auto v = foam->cbeginValueOn(); v; ++v) out.foam.push_back({index(v.getCoord()), *v});
  } catch (const openvdb::Exception& e) {
    throw liquid::Error(path.string() + ": " + e.what());
  }
  return out;
}

}  // namespace liquid
