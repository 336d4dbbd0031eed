// The shipped scenes, for the CPU tests: where they are, every one of them, and one by name.
#pragma once

#include "liquid/physics/setup.h"
#include "liquid/scene.h"

#include <algorithm>
#include <filesystem>
#include <vector>

namespace test_scenes {

inline const std::filesystem::path k_scene_dir = std::filesystem::path(LIQUID_ASSET_DIR) / "scenes";

// Every .json file in assets/scenes/, sorted.
inline std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(k_scene_dir))
    if (entry.path().extension() == ".json") paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  return paths;
}

inline liquid::Scene scene_of(const char* file) { return liquid::load_scene(k_scene_dir / file); }

inline liquid::SimulationSetup setup_of(const char* file, const liquid::DeviceLimits& limits = {}) {
  return liquid::make_setup(scene_of(file), limits);
}

}  // namespace test_scenes
