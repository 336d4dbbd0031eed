// The files of one written frame: the PNG, and on request the particles (PLY), the secondary
// particles (whitewater PLY), the grids (OpenVDB, with the foam's grid when the scene has
// whitewater) and the surface (a level-set VDB and a mesh), all of one instant: the node's time
// after the frame's steps.
#pragma once

#include "engine/io/png.h"
#include "liquid/node.h"
#include "tools/liquid_capture/options.h"

#include <filesystem>
#include <string>

namespace engine::vk {
class Context;
}

namespace capture {

// Whether this build can write OpenVDB files (OpenVDB was found when it was configured).
bool volume_export_available();

// What writing a frame measured, for stats.csv.
struct FrameExports {
  double surface_ms = 0.0;       // the surface export's wall time (level set, mesh and both files); 0 without it
  // The whitewater's wall time: the read-back, its PLY and the foam grid's splat; 0 when not read back.
  double whitewater_ms = 0.0;
  int whitewater_particles = 0;  // the live secondary particles read back
};

class FrameWriter {
 public:
  FrameWriter(const RunSettings& settings, engine::vk::Context& context, std::filesystem::path folder,
              std::string scene_name)
      : settings_(settings), context_(context), folder_(std::move(folder)), scene_name_(std::move(scene_name)) {}

  // Writes frame `frame` of `node` (with no frame in flight); each file through a temporary name.
  FrameExports write(int frame, liquid::LiquidNode& node, const liquid::ParticleSnapshot& particles,
                     const engine::vk::Rgba8Image& image) const;

 private:
  const RunSettings& settings_;
  engine::vk::Context& context_;
  std::filesystem::path folder_;
  std::string scene_name_;
};

}  // namespace capture
