#include "tools/liquid_viewer/session.h"

#include "liquid/physics/setup.h"
#include "liquid/render/view2d.h"
#include "liquid/solver/simulation.h"

#include <algorithm>
#include <cmath>
#include <system_error>

namespace viewer {

Session::Session(engine::vk::Context& context, const std::filesystem::path& path, uint32_t frames_in_flight,
                 int max_steps_per_frame, std::optional<liquid::GridPath> grid_path)
    : context_(context),
      path_(path),
      frames_in_flight_(frames_in_flight),
      max_steps_(max_steps_per_frame),
      grid_path_(grid_path) {
  stamp_ = stamp();
  create(liquid::load_scene(path));
}

std::filesystem::file_time_type Session::stamp() const {
  std::error_code error;
  const auto t = std::filesystem::last_write_time(path_, error);
  return error ? std::filesystem::file_time_type{} : t;
}

void Session::create(const liquid::Scene& scene) {
  // Build the new node and renderer first: if either throws, the running scene is untouched.
  auto node = std::make_unique<liquid::LiquidNode>(
      context_, scene,
      liquid::LiquidOptions{.frames_in_flight = frames_in_flight_,
                            .max_steps_per_frame = std::max(max_steps_, scene.substeps),
                            .grid_path = grid_path_});
  auto renderer = std::make_unique<liquid::LiquidRenderer>(context_, *node, view_);
  renderer_.reset();
  node_ = std::move(node);
  renderer_ = std::move(renderer);
  scene_ = scene;
  camera_ = OrbitCamera::from(liquid::default_camera(*node_));
}

bool Session::needs_view(uint32_t width, uint32_t height, const Settings& switches) const {
  return !renderer_ || width != view_.width || height != view_.height || switches.fxaa != view_.fxaa ||
         (switches.particles && node_->dimension() == 2) != view_.draw_particles ||
         switches.whitewater != view_.whitewater;
}

void Session::set_view(uint32_t width, uint32_t height, const Settings& switches) {
  if (!needs_view(width, height, switches)) return;
  liquid::RenderSettings next = view_;
  next.width = width;
  next.height = height;
  next.fxaa = switches.fxaa;
  next.draw_particles = switches.particles && node_->dimension() == 2;
  next.whitewater = switches.whitewater;
  view_ = next;
  renderer_.reset();
  renderer_ = std::make_unique<liquid::LiquidRenderer>(context_, *node_, view_);
}

void Session::reset() {
  const auto parameters = node_->runtime_parameters();
  create(scene_);  // the camera too goes back to the scene's
  node_->set_runtime_parameters(parameters);
}

std::optional<std::string> Session::reload() {
  stamp_ = stamp();
  try {
    create(liquid::load_scene(path_));
    error_.clear();
    return std::nullopt;
  } catch (const std::exception& e) {
    error_ = e.what();
    return error_;
  }
}

bool Session::file_changed() { return stamp() != stamp_; }

ViewMapping Session::mapping() const {
  ViewMapping m;
  m.dimension = node_->dimension();
  m.size = {float(view_.width), float(view_.height)};
  const liquid::SimulationSetup& setup = simulation_of(*node_).setup();
  m.domain = setup.domain;
  m.height_field = setup.shallow_water;
  m.water_level = setup.rest_depth;
  if (m.perspective()) {
    m.inverse_view_projection = glm::inverse(renderer_->view_projection(camera_.view()));
  } else {
    const liquid::View2dLayout layout = liquid::fit_view2d(glm::vec2(m.domain), view_.width, view_.height);
    m.origin = layout.origin;
    m.pixels_per_metre = layout.pixels_per_metre;
  }
  return m;
}

std::optional<glm::vec3> Session::surface_hit(glm::vec3 origin, glm::vec3 direction) {
  if (simulation_of(*node_).setup().shallow_water) return height_field_hit(origin, direction);
  const liquid::SimulationSetup& s = simulation_of(*node_).setup();
  const glm::vec3 domain = s.domain;
  // The ray's stretch inside the domain box (slab test).
  float t0 = 0.0f, t1 = 1e30f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(direction[a]) < 1e-9f) {
      if (origin[a] < 0.0f || origin[a] > domain[a]) return std::nullopt;
      continue;
    }
    float ta = (0.0f - origin[a]) / direction[a], tb = (domain[a] - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 >= t1) return std::nullopt;
  const std::vector<float> ratio = node_->read_density_ratio();
  const glm::ivec3 n = s.grid_cells;
  if (ratio.size() < size_t(n.x) * n.y * n.z) return std::nullopt;
  const float step = 0.5f * s.cell_size;
  for (float t = t0; t <= t1; t += step) {
    const glm::vec3 p = origin + t * direction;
    const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor(p / s.cell_size)), glm::ivec3(0), n - 1);
    if (ratio[size_t(c.x) + size_t(n.x) * (size_t(c.y) + size_t(n.y) * size_t(c.z))] >= 0.5f) return p;
  }
  return std::nullopt;
}

std::optional<glm::vec3> Session::height_field_hit(glm::vec3 origin, glm::vec3 direction) {
  const liquid::SimulationSetup& s = simulation_of(*node_).setup();
  const glm::ivec2 n(s.grid_cells.x, s.grid_cells.y);
  const std::vector<float> ratio = node_->read_density_ratio();
  if (ratio.size() < size_t(n.x) * size_t(n.y)) return std::nullopt;
  // The surface the view draws over domain point (x, y): the ground plus the water's depth there.
  const auto surface = [&](glm::vec2 p) {
    const glm::ivec2 c = glm::clamp(glm::ivec2(glm::floor(p / s.cell_size)), glm::ivec2(0), n - 1);
    return liquid::ground_height(scene_, p) + s.rest_depth * ratio[size_t(c.x) + size_t(n.x) * size_t(c.y)];
  };
  // The ray's stretch over the plane (world x and z inside the domain), marched in half cells
  // until it first goes below the surface.
  float t0 = 0.0f, t1 = 1e30f;
  for (int a : {0, 2}) {
    const float extent = a == 0 ? s.domain.x : s.domain.y;
    if (std::abs(direction[a]) < 1e-9f) {
      if (origin[a] < 0.0f || origin[a] > extent) return std::nullopt;
      continue;
    }
    float ta = -origin[a] / direction[a], tb = (extent - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  for (float t = t0; t <= t1; t += 0.5f * s.cell_size) {
    const glm::vec3 p = origin + t * direction;
    if (p.y <= surface({p.x, p.z})) return p;
  }
  return std::nullopt;
}

}  // namespace viewer
