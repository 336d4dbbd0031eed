#include "tools/liquid_capture/frame_writer.h"

#include "liquid/export/ply.h"
#include "liquid/export/volume.h"
#include "liquid/export/whitewater_ply.h"
#include "liquid/solver/simulation.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/surface.h"
#include "liquid/export/vdb.h"
#endif

#include <chrono>
#include <stdexcept>

namespace capture {

namespace {

// The wall time of work(), ms.
template <class Work>
double timed_ms(Work&& work) {
  const auto started = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace

bool volume_export_available() {
#if RASTERLIQUIDS_HAVE_OPENVDB
  return true;
#else
  return false;
#endif
}

FrameExports FrameWriter::write(int frame, liquid::LiquidNode& node, const liquid::ParticleSnapshot& particles,
                                const engine::vk::Rgba8Image& image) const {
  engine::vk::write_png(folder_ / settings_.frames.name(frame), image);
  const double fps = settings_.plan.frames_per_second();
  FrameExports exports;
  // The secondary particles are the steps' state: they need no grids rebuilt.
  const bool scene_has_whitewater = node.scene().whitewater.has_value();
  std::vector<liquid::WhitewaterParticle> whitewater;
  if (settings_.reads_whitewater(scene_has_whitewater))
    exports.whitewater_ms = timed_ms([&] {
      whitewater = simulation_of(node).read_whitewater();
      if (settings_.whitewater)
        liquid::write_whitewater_ply(folder_ / settings_.whitewater->name(frame), whitewater,
                                     liquid::WhitewaterPlyFrame{frame, node.time(), fps});
    });
  exports.whitewater_particles = int(whitewater.size());
  if (!settings_.exports_grids()) return exports;
  liquid::VolumeFrame volume = liquid::read_volume(context_, node);
  if (settings_.particles)
    liquid::write_ply(folder_ / settings_.particles->name(frame), particles,
                      liquid::PlyFrame{frame, node.time(), liquid::sample_density(volume, particles.positions), fps});
  if (settings_.volumes) {
#if RASTERLIQUIDS_HAVE_OPENVDB
    if (scene_has_whitewater)
      exports.whitewater_ms += timed_ms([&] { volume.foam = liquid::foam_number_density(volume, whitewater); });
    liquid::write_vdb(folder_ / settings_.volumes->name(frame), volume,
                      liquid::VdbFrame{frame, node.time(), scene_name_, fps});
#else
    throw std::logic_error("volume export requested in a build without OpenVDB");
#endif
  }
  if (!settings_.surfaces) return exports;
#if RASTERLIQUIDS_HAVE_OPENVDB
  exports.surface_ms = timed_ms([&] {
    const liquid::LiquidSurface surface(
        volume, liquid::SurfaceSettings{.voxels_per_cell = settings_.surface_voxels_per_cell,
                                        .adaptivity = settings_.surface_adaptivity});
    surface.write_vdb(folder_ / settings_.surfaces->name(frame), liquid::VdbFrame{frame, node.time(), scene_name_, fps});
    const std::string mesh_name = settings_.meshes->name(frame);
    liquid::write_mesh(folder_ / mesh_name, surface.mesh(volume), liquid::MeshFrame{frame, node.time(), fps},
                       mesh_name.ends_with(".obj") ? liquid::MeshFormat::Obj : liquid::MeshFormat::Ply);
  });
  return exports;
#else
  throw std::logic_error("surface export requested in a build without OpenVDB");
#endif
}

}  // namespace capture
