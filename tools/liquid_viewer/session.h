// One scene running in the viewer: its file, the liquid node and renderer, the 3D camera, and
// reloading (by key, or when the file changes on disk) that keeps the old scene running when the
// new one fails to load, with the error kept for the window.
#pragma once

#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/scene.h"
#include "tools/liquid_viewer/controls.h"
#include "tools/liquid_viewer/input.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace engine::vk {
class Context;
}

namespace viewer {

class Session {
 public:
  // Throws (liquid::SceneError and others) when the scene cannot be loaded or run.
  // `grid_path`: the 3D path to force (--3d-path), or empty for LIQUID_3D_PATH or the device's best.
  Session(engine::vk::Context& context, const std::filesystem::path& path, uint32_t frames_in_flight,
          int max_steps_per_frame, std::optional<liquid::GridPath> grid_path = std::nullopt);

  const std::filesystem::path& path() const { return path_; }
  liquid::LiquidNode& node() { return *node_; }
  liquid::LiquidRenderer& renderer() { return *renderer_; }
  OrbitCamera& camera() { return camera_; }
  int dimension() const { return node_->dimension(); }

  // Whether set_view() with these values would create a new renderer.
  bool needs_view(uint32_t width, uint32_t height, const Settings& switches) const;
  // (Re)creates the renderer for this size and the switches' FXAA, particles and whitewater (the
  // device must be idle).
  void set_view(uint32_t width, uint32_t height, const Settings& switches);
  // Back to the scene's first step and its default camera (the device must be idle); keeps the
  // live parameters.
  void reset();
  // Reloads the file (the device must be idle). On failure the running scene stays and the
  // error is returned (also kept in error()).
  std::optional<std::string> reload();
  // Whether the file changed on disk since it was last loaded (or tried).
  bool file_changed();
  const std::string& error() const { return error_; }

  // The view's pixel mapping at the renderer's size.
  ViewMapping mapping() const;
  liquid::CameraView camera_view() const { return camera_.view(); }
  // Where a view ray (world space) first meets the liquid, from the density read back now (no
  // frame of the node may be in flight), or nothing: 3D, rho/rho0 >= 0.5; shallow water, the
  // height field's surface (ground plus water depth), in the view's world.
  std::optional<glm::vec3> surface_hit(glm::vec3 origin, glm::vec3 direction);

 private:
  std::optional<glm::vec3> height_field_hit(glm::vec3 origin, glm::vec3 direction);
  void create(const liquid::Scene& scene);
  std::filesystem::file_time_type stamp() const;

  engine::vk::Context& context_;
  std::filesystem::path path_;
  uint32_t frames_in_flight_;
  int max_steps_;
  std::optional<liquid::GridPath> grid_path_;
  liquid::Scene scene_;
  std::unique_ptr<liquid::LiquidNode> node_;
  std::unique_ptr<liquid::LiquidRenderer> renderer_;
  liquid::RenderSettings view_{};
  OrbitCamera camera_;
  std::filesystem::file_time_type stamp_{};
  std::string error_;
};

}  // namespace viewer
