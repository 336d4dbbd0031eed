// The files of one written frame: the PNG, and on request the particles (PLY), the grids (OpenVDB)
// and the surface (a level-set VDB and a mesh), all of one instant: the node's time after the
// frame's steps.
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

class FrameWriter {
 public:
  FrameWriter(const RunSettings& settings, engine::vk::Context& context, std::filesystem::path folder,
              std::string scene_name)
      : settings_(settings), context_(context), folder_(std::move(folder)), scene_name_(std::move(scene_name)) {}

  // Writes frame `frame` of `node` (with no frame in flight); each file through a temporary name.
  // Returns the wall time of the surface export (building and writing both files), ms; 0 without it.
  double write(int frame, liquid::LiquidNode& node, const liquid::ParticleSnapshot& particles,
             const engine::vk::Rgba8Image& image) const;

 private:
  const RunSettings& settings_;
  engine::vk::Context& context_;
  std::filesystem::path folder_;
  std::string scene_name_;
};

}  // namespace capture
