#include "tools/liquid_capture/frame_writer.h"

#include "liquid/export/ply.h"
#include "liquid/export/volume.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/surface.h"
#include "liquid/export/vdb.h"
#endif

#include <chrono>
#include <stdexcept>

namespace capture {

bool volume_export_available() {
#if RASTERLIQUIDS_HAVE_OPENVDB
  return true;
#else
  return false;
#endif
}

double FrameWriter::write(int frame, liquid::LiquidNode& node, const liquid::ParticleSnapshot& particles,
                          const engine::vk::Rgba8Image& image) const {
  engine::vk::write_png(folder_ / settings_.frames.name(frame), image);
  if (!settings_.exports_grids()) return 0.0;
  const liquid::VolumeFrame volume = liquid::read_volume(context_, node);
  if (settings_.particles)
    liquid::write_ply(folder_ / settings_.particles->name(frame), particles,
                      liquid::PlyFrame{frame, node.time(), liquid::sample_density(volume, particles.positions),
                                       settings_.plan.frames_per_second()});
  if (settings_.volumes) {
#if RASTERLIQUIDS_HAVE_OPENVDB
    liquid::write_vdb(folder_ / settings_.volumes->name(frame), volume,
                      liquid::VdbFrame{frame, node.time(), scene_name_, settings_.plan.frames_per_second()});
#else
    throw std::logic_error("volume export requested in a build without OpenVDB");
#endif
  }
  if (!settings_.surfaces) return 0.0;
#if RASTERLIQUIDS_HAVE_OPENVDB
  const auto started = std::chrono::steady_clock::now();
  const liquid::LiquidSurface surface(
      volume, liquid::SurfaceSettings{.voxels_per_cell = settings_.surface_voxels_per_cell,
                                      .adaptivity = settings_.surface_adaptivity});
  surface.write_vdb(folder_ / settings_.surfaces->name(frame),
                    liquid::VdbFrame{frame, node.time(), scene_name_, settings_.plan.frames_per_second()});
  const std::string mesh_name = settings_.meshes->name(frame);
  liquid::write_mesh(folder_ / mesh_name, surface.mesh(volume),
                     liquid::MeshFrame{frame, node.time(), settings_.plan.frames_per_second()},
                     mesh_name.ends_with(".obj") ? liquid::MeshFormat::Obj : liquid::MeshFormat::Ply);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
#else
  throw std::logic_error("surface export requested in a build without OpenVDB");
#endif
}

}  // namespace capture
