#include "tools/liquid_capture/frame_writer.h"

#include "liquid/export/ply.h"
#include "liquid/export/volume.h"
#if RASTERLIQUIDS_HAVE_OPENVDB
#include "liquid/export/vdb.h"
#endif

#include <stdexcept>

namespace capture {

bool volume_export_available() {
#if RASTERLIQUIDS_HAVE_OPENVDB
  return true;
#else
  return false;
#endif
}

void FrameWriter::write(int frame, liquid::LiquidNode& node, const liquid::ParticleSnapshot& particles,
                        const engine::vk::Rgba8Image& image) const {
  engine::vk::write_png(folder_ / settings_.frames.name(frame), image);
  if (!settings_.particles && !settings_.volumes) return;
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
}

}  // namespace capture
