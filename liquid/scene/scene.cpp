// The scene's keys: which exist, their units, defaults and allowed ranges (see the README's scene
// table). JSON syntax and duplicate keys are handled in json.cpp.
#include "liquid/scene.h"
#include "liquid/scene/mesh_file.h"
#include "liquid/scene/number_keys.h"
#include "liquid/scene/reader.h"
#include "shaders/liquid/shared.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <vector>

namespace liquid::scene_reader {
namespace {

constexpr double k_max_domain_extent = 100.0;  // m
constexpr int k_min_grid_resolution = 8;
constexpr int k_max_grid_resolution = 2048;
constexpr double k_max_gravity = 1000.0;        // m/s^2 per component
constexpr double k_max_speed = 1000.0;          // m/s per component
constexpr double k_max_frequency = 1000.0;      // Hz
constexpr double k_max_angular_speed = 1000.0;  // rad/s per component (about 160 turns a second)
constexpr int k_max_emitter_capacity = 1 << 24;  // 16M particles
constexpr double k_max_body_density = 1e5;      // kg/m^3, past any solid (osmium: 22590)
constexpr double k_max_body_mass = 1e9;         // kg

// Shallow water derives k and gamma (P = g h), so giving them would be silently ignored.
constexpr const char* k_derived_in_shallow_water = "not used in shallow_water mode (k = |gravity| * rest_depth, gamma = 1)";

// The plain number keys (number_keys.h): a new one is a row here and its member in Scene.
const NumberKey k_number_keys[] = {
    {"grid_resolution", &Scene::grid_resolution, k_min_grid_resolution, k_max_grid_resolution},
    {"density", &Scene::density, 1.0, 1e5},
    {"stiffness", &Scene::stiffness, 0.0, 1e6, true, k_derived_in_shallow_water},
    {"gamma", &Scene::gamma, 1.0, 10.0, false, k_derived_in_shallow_water},
    {"kernel_radius_cells", &Scene::kernel_radius_cells, 1.0, gpu::k_max_kernel_radius_cells},
    {"pic_ratio", &Scene::pic_ratio, 0.0, 1.0},
    {"pic_ratio_reference_step", &Scene::pic_ratio_reference_step, 1e-6, 0.1},
    {"time_step", &Scene::time_step, k_min_time_step, k_max_time_step},
    {"substeps", &Scene::substeps, 1, 1000},
    {"wall_margin_cells", &Scene::wall_margin_cells, 0.0, 4.0},
    {"position_correction", &Scene::position_correction, 0.0, 1.0, false, "not used in shallow_water mode"},
    {"projection_iterations", &Scene::projection_iterations, 0, 1000, false, "not used in shallow_water mode"},
};

// The keys read by code of their own (vectors, choices, objects, arrays, cross-checked numbers).
constexpr const char* k_structured_keys[] = {
    "name", "dimension", "mode", "domain", "gravity", "particle_spacing", "rest_density", "adaptive_time_step",
    "splat_format", "pressure_force", "splat", "transfer", "rest_depth", "fluid_blocks", "emitters", "obstacles", "ground",
    "camera", "whitewater"};

void read_number_key(const Reader& r, const Json& value, const NumberKey& row, Scene& scene) {
  std::visit(
      [&](auto member) {
        using Value = std::remove_reference_t<decltype(scene.*member)>;
        if constexpr (std::is_same_v<Value, int> || std::is_same_v<Value, std::optional<int>>)
          scene.*member = r.integer_in(value, row.key, int(row.lo), int(row.hi));
        else
          scene.*member = float(r.number_in(value, row.key, row.lo, row.hi, row.lo_open));
      },
      row.member);
}

// ---- Nested objects --------------------------------------------------------------------------

FluidBlock read_fluid_block(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"min", "max", "velocity"});
  FluidBlock block;
  block.min = r.point_in_domain(r.require(value, path, "min"), child(path, "min"));
  block.max = r.point_in_domain(r.require(value, path, "max"), child(path, "max"));
  for (int a = 0; a < r.dimension(); ++a)
    if (!(block.min[a] < block.max[a]))
      r.fail(child(path, "max"), "must be greater than min on every axis (axis " + std::to_string(a) + ": min " +
                                        format_number(block.min[a]) + ", max " + format_number(block.max[a]) + ")");
  if (const Json* v = Reader::find(value, "velocity"))
    block.velocity = r.scene_vector(*v, child(path, "velocity"), k_max_speed);
  return block;
}

Emitter read_emitter(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"position", "velocity", "radius", "start_time", "stop_time", "capacity"});
  Emitter emitter;
  emitter.position = r.point_in_domain(r.require(value, path, "position"), child(path, "position"));
  emitter.velocity = r.scene_vector(r.require(value, path, "velocity"), child(path, "velocity"), k_max_speed);
  if (glm::dot(emitter.velocity, emitter.velocity) == 0.0f)
    r.fail(child(path, "velocity"), "must be nonzero (it sets the jet's direction and flow rate)");
  emitter.radius = float(r.number_in(r.require(value, path, "radius"), child(path, "radius"), 0.0, k_max_length, true));
  if (const Json* v = Reader::find(value, "start_time"))
    emitter.start_time = float(r.number_in(*v, child(path, "start_time"), 0.0, double(FLT_MAX)));
  if (const Json* v = Reader::find(value, "stop_time")) {
    emitter.stop_time = float(r.number(*v, child(path, "stop_time")));
    if (!(emitter.stop_time > emitter.start_time))
      r.fail(child(path, "stop_time"), "must be greater than start_time (" + format_number(emitter.start_time) +
                                           "), got " + format_number(emitter.stop_time));
  }
  emitter.capacity =
      r.integer_in(r.require(value, path, "capacity"), child(path, "capacity"), 1, k_max_emitter_capacity);
  return emitter;
}

Metaball read_metaball(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"center", "radius"});
  Metaball ball;
  ball.center = r.scene_vector(r.require(value, path, "center"), child(path, "center"));
  ball.radius = float(r.number_in(r.require(value, path, "radius"), child(path, "radius"), 0.0, k_max_length, true));
  return ball;
}

void read_oscillation(const Reader& r, const Json& value, const std::string& path, Obstacle& obstacle) {
  r.check_keys(value, path, {"amplitude", "frequency"});
  obstacle.oscillation_amplitude = r.scene_vector(r.require(value, path, "amplitude"), child(path, "amplitude"));
  obstacle.oscillation_frequency =
      float(r.number_in(r.require(value, path, "frequency"), child(path, "frequency"), 0.0, k_max_frequency));
}

// "rotation": {"axis": [x, y, z], "degrees": a}, or [x, y, z], degrees about x, then y, then z. A
// 2D sphere or box turns about z only (the axis may then be left out); a 2D mesh may turn any way,
// its cross-section at z = 0 follows.
glm::quat read_rotation(const Reader& r, const Json& value, const std::string& path, bool mesh) {
  const bool about_z_only = r.dimension() == 2 && !mesh;
  if (value.is_array()) {
    const glm::vec3 radians = glm::radians(r.vector(value, path, 3, 360.0));
    if (about_z_only && (radians.x != 0.0f || radians.y != 0.0f))
      r.fail(path, "must be [0, 0, degrees] in 2D (a 2D obstacle turns about z)");
    return glm::angleAxis(radians.z, glm::vec3(0, 0, 1)) * glm::angleAxis(radians.y, glm::vec3(0, 1, 0)) *
           glm::angleAxis(radians.x, glm::vec3(1, 0, 0));
  }
  if (!value.is_object())
    r.fail(path, std::string("must be {\"axis\", \"degrees\"} or [x, y, z] degrees, got ") + value.type_name());
  r.check_keys(value, path, {"axis", "degrees"});
  const float degrees = float(r.number_in(r.require(value, path, "degrees"), child(path, "degrees"), -360.0, 360.0));
  glm::vec3 axis(0.0f, 0.0f, 1.0f);
  if (const Json* v = Reader::find(value, "axis")) {
    axis = r.vector(*v, child(path, "axis"), 3);
    if (!(glm::length(axis) > 0.0f)) r.fail(child(path, "axis"), "must be nonzero");
    axis = glm::normalize(axis);
    if (about_z_only && (axis.x != 0.0f || axis.y != 0.0f))
      r.fail(child(path, "axis"), "must be [0, 0, 1] in 2D (a 2D obstacle turns about z)");
  } else if (!about_z_only) {
    r.fail(child(path, "axis"), "missing required key (3D rotations need an axis)");
  }
  return glm::angleAxis(glm::radians(degrees), axis);
}

// "angular_velocity" (rad/s, world frame): [x, y, z] in 3D, one number (about z, counter-clockwise)
// in 2D, where an obstacle turns about z only.
glm::vec3 read_angular_velocity(const Reader& r, const Json& value, const std::string& path) {
  if (r.dimension() == 2) {
    if (!value.is_number())
      r.fail(path, std::string("must be one number in 2D (rad/s about z), got ") + value.type_name());
    return glm::vec3(0.0f, 0.0f, float(r.number_in(value, path, -k_max_angular_speed, k_max_angular_speed)));
  }
  return r.vector(value, path, 3, k_max_angular_speed);
}

// "dynamic": true with "density" (kg/m^3) or "mass" (kg; in 2D, kg per metre of depth).
void read_body(const Reader& r, const Json& value, const std::string& path, Obstacle& obstacle) {
  const Json* dynamic = Reader::find(value, "dynamic");
  if (dynamic && !dynamic->is_boolean()) r.fail(child(path, "dynamic"), std::string("must be true or false, got ") + dynamic->type_name());
  obstacle.dynamic = dynamic && dynamic->get<bool>();
  const Json* density = Reader::find(value, "density");
  const Json* mass = Reader::find(value, "mass");
  if (!obstacle.dynamic) {
    if (density || mass) r.fail(child(path, density ? "density" : "mass"), "only allowed with \"dynamic\": true");
    return;
  }
  // The shapes liquid/physics/body.cpp has mass properties for.
  if (obstacle.shape != ObstacleShape::Sphere && obstacle.shape != ObstacleShape::Box && obstacle.shape != ObstacleShape::Mesh)
    r.fail(child(path, "dynamic"), "\"" + std::string(k_obstacle_shape_keys[size_t(obstacle.shape)]) +
                                       "\" obstacles cannot be dynamic (only spheres, boxes and meshes)");
  if (obstacle.shape == ObstacleShape::Mesh && r.dimension() == 2)
    r.fail(child(path, "dynamic"), "a mesh obstacle can be dynamic in 3D only");
  if (Reader::find(value, "oscillation")) r.fail(child(path, "oscillation"), "not allowed on a dynamic obstacle (the liquid moves it)");
  if (density && mass) r.fail(child(path, "mass"), "give density or mass, not both");
  if (!density && !mass) r.fail(child(path, "density"), "missing required key (a dynamic obstacle needs density or mass)");
  if (density) obstacle.density = float(r.number_in(*density, child(path, "density"), 0.0, k_max_body_density, true));
  if (mass) obstacle.mass = float(r.number_in(*mass, child(path, "mass"), 0.0, k_max_body_mass, true));
}

// A mesh obstacle's file (relative to the scene's folder) and uniform scale (its rotation is the
// obstacle's, read_rotation()).
TriangleMesh read_mesh(const Reader& r, const Json& value, const std::string& path) {
  const std::string file_path = child(path, "file");
  const std::string file = r.string(r.require(value, path, "file"), file_path);
  if (file.empty()) r.fail(file_path, "must name a mesh file (OBJ or PLY)");
  TriangleMesh mesh;
  try {
    mesh = load_mesh_file(std::filesystem::path(r.source()).parent_path() / file);
  } catch (const SceneError& e) {
    r.fail(file_path, e.what());
  }
  if (const Json* v = Reader::find(value, "scale"))
    mesh.scale = float(r.number_in(*v, child(path, "scale"), 0.0, k_max_length, true));
  return mesh;
}

Obstacle read_obstacle(const Reader& r, const Json& value, const std::string& path) {
  if (!value.is_object()) r.fail(path, std::string("must be an object, got ") + value.type_name());
  Obstacle obstacle;
  obstacle.shape = ObstacleShape(r.choice(r.require(value, path, "shape"), child(path, "shape"), k_obstacle_shape_keys));
  switch (obstacle.shape) {
    case ObstacleShape::Sphere:
      r.check_keys(value, path, {"shape", "center", "radius", "velocity", "oscillation", "rotation", "angular_velocity", "dynamic", "density", "mass"});
      obstacle.center = r.scene_vector(r.require(value, path, "center"), child(path, "center"));
      obstacle.radius =
          float(r.number_in(r.require(value, path, "radius"), child(path, "radius"), 0.0, k_max_length, true));
      break;
    case ObstacleShape::Box: {
      r.check_keys(value, path, {"shape", "center", "half_extent", "velocity", "oscillation", "rotation", "angular_velocity", "dynamic", "density", "mass"});
      obstacle.center = r.scene_vector(r.require(value, path, "center"), child(path, "center"));
      const std::string extent_path = child(path, "half_extent");
      obstacle.half_extent = r.scene_vector(r.require(value, path, "half_extent"), extent_path);
      for (int a = 0; a < r.dimension(); ++a)
        if (!(obstacle.half_extent[a] > 0.0f))
          r.fail(element(extent_path, size_t(a)), "must be > 0, got " + format_number(obstacle.half_extent[a]));
      break;
    }
    case ObstacleShape::Metaballs: {
      r.check_keys(value, path, {"shape", "balls", "threshold", "velocity", "oscillation", "dynamic", "density", "mass"});
      const std::string balls_path = child(path, "balls");
      const Json& balls = r.require(value, path, "balls");
      if (!balls.is_array() || balls.empty()) r.fail(balls_path, "must be a non-empty array of {center, radius}");
      glm::vec3 centroid(0.0f);
      for (size_t i = 0; i < balls.size(); ++i) {
        obstacle.balls.push_back(read_metaball(r, balls[i], element(balls_path, i)));
        centroid += obstacle.balls.back().center;
      }
      // Ball centres are written in domain coordinates; the obstacle is placed at their centroid
      // and the balls are stored relative to it, as the shaders and obstacles.cpp expect.
      obstacle.center = centroid / float(obstacle.balls.size());
      for (Metaball& ball : obstacle.balls) ball.center -= obstacle.center;
      if (const Json* v = Reader::find(value, "threshold"))
        obstacle.threshold = float(r.number_in(*v, child(path, "threshold"), 0.0, 1.0, true, true));
      break;
    }
    case ObstacleShape::Mesh:
      r.check_keys(value, path, {"shape", "center", "file", "rotation", "angular_velocity", "scale", "velocity", "oscillation",
                                 "dynamic", "density", "mass"});
      obstacle.center = r.scene_vector(r.require(value, path, "center"), child(path, "center"));
      obstacle.mesh = read_mesh(r, value, path);
      break;
  }
  if (const Json* v = Reader::find(value, "velocity"))
    obstacle.velocity = r.scene_vector(*v, child(path, "velocity"), k_max_speed);
  if (const Json* v = Reader::find(value, "oscillation")) read_oscillation(r, *v, child(path, "oscillation"), obstacle);
  if (const Json* v = Reader::find(value, "rotation")) obstacle.rotation = read_rotation(r, *v, child(path, "rotation"), obstacle.shape == ObstacleShape::Mesh);
  if (const Json* v = Reader::find(value, "angular_velocity"))
    obstacle.angular_velocity = read_angular_velocity(r, *v, child(path, "angular_velocity"));
  if (obstacle.shape == ObstacleShape::Mesh) obstacle.mesh.rotation = obstacle.rotation;  // voxelized turned
  read_body(r, value, path, obstacle);
  return obstacle;
}

GroundHill read_ground_hill(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"center", "height", "width"});
  GroundHill hill;
  const glm::vec3 center = r.vector(r.require(value, path, "center"), child(path, "center"), 2);
  hill.center = glm::vec2(center);
  hill.height =
      float(r.number_in(r.require(value, path, "height"), child(path, "height"), -k_max_length, k_max_length));
  hill.width = float(r.number_in(r.require(value, path, "width"), child(path, "width"), 0.0, k_max_length, true));
  return hill;
}

Camera read_camera(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"position", "target", "fov_y_degrees"});
  Camera camera;
  camera.position = r.vector(r.require(value, path, "position"), child(path, "position"), 3, 10.0 * k_max_length);
  camera.target = r.vector(r.require(value, path, "target"), child(path, "target"), 3, 10.0 * k_max_length);
  if (camera.position == camera.target) r.fail(child(path, "target"), "must differ from position");
  if (const Json* v = Reader::find(value, "fov_y_degrees"))
    camera.fov_y_degrees = float(r.number_in(*v, child(path, "fov_y_degrees"), 1.0, 170.0));
  return camera;
}

// A potential's range [lo, hi]: 0 <= lo < hi <= bound.
glm::vec2 read_range(const Reader& r, const Json& value, const std::string& path, double bound) {
  const glm::vec3 range = r.vector(value, path, 2, bound);
  if (!(range.x >= 0.0f && range.x < range.y))
    r.fail(path, "must be [lo, hi] with 0 <= lo < hi, got [" + format_number(range.x) + ", " + format_number(range.y) + "]");
  return {range.x, range.y};
}

Whitewater read_whitewater(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path,
               {"slots_per_particle", "lifetime", "trapped_air_rate", "crest_rate", "trapped_air_range", "crest_range",
                "speed_range", "spray_density", "bubble_density", "spray_drag", "bubble_buoyancy", "bubble_drag"});
  Whitewater w;
  const auto number = [&](const char* key, float& member, double lo, double hi, bool lo_open = false) {
    if (const Json* v = Reader::find(value, key)) member = float(r.number_in(*v, child(path, key), lo, hi, lo_open));
  };
  if (const Json* v = Reader::find(value, "slots_per_particle"))
    w.slots_per_particle = r.integer_in(*v, child(path, "slots_per_particle"), 1, gpu::k_max_whitewater_slots);
  number("lifetime", w.lifetime, 0.0, 1000.0, true);
  number("trapped_air_rate", w.trapped_air_rate, 0.0, 1e6);
  number("crest_rate", w.crest_rate, 0.0, 1e6);
  if (const Json* v = Reader::find(value, "trapped_air_range"))
    w.trapped_air_range = read_range(r, *v, child(path, "trapped_air_range"), k_max_speed);
  if (const Json* v = Reader::find(value, "crest_range"))
    w.crest_range = read_range(r, *v, child(path, "crest_range"), 1e6);
  if (const Json* v = Reader::find(value, "speed_range"))
    w.speed_range = read_range(r, *v, child(path, "speed_range"), k_max_speed);
  number("spray_density", w.spray_density, 0.0, 1.0);
  number("bubble_density", w.bubble_density, 0.0, 2.0);
  if (!(w.spray_density < w.bubble_density))
    r.fail(child(path, "bubble_density"), "must be greater than spray_density (" + format_number(w.spray_density) +
                                              "), got " + format_number(w.bubble_density));
  number("spray_drag", w.spray_drag, 0.0, 1000.0);
  number("bubble_buoyancy", w.bubble_buoyancy, 0.0, 100.0);
  number("bubble_drag", w.bubble_drag, 0.0, 1000.0);
  return w;
}

AdaptiveTimeStep read_adaptive_time_step(const Reader& r, const Json& value, const std::string& path) {
  r.check_keys(value, path, {"acoustic_cfl", "velocity_cfl"});
  AdaptiveTimeStep a;
  if (const Json* v = Reader::find(value, "acoustic_cfl"))
    a.acoustic_cfl = float(r.number_in(*v, child(path, "acoustic_cfl"), 0.0, k_max_acoustic_cfl, true));
  if (const Json* v = Reader::find(value, "velocity_cfl"))
    a.velocity_cfl = float(r.number_in(*v, child(path, "velocity_cfl"), 0.0, 2.0, true));
  return a;
}

// Reads an optional array member, each element with `read_one`; at most `max_count` elements.
template <typename T, typename ReadOne>
std::vector<T> read_array(const Reader& r, const Json& object, const char* key, ReadOne read_one) {
  std::vector<T> items;
  const Json* value = Reader::find(object, key);
  if (!value) return items;
  if (!value->is_array()) r.fail(key, std::string("must be an array, got ") + value->type_name());
  for (size_t i = 0; i < value->size(); ++i) items.push_back(read_one(r, (*value)[i], element(key, i)));
  return items;
}

// ---- Top level ---------------------------------------------------------------------------------

void read_space(Reader& r, const Json& doc, Scene& scene) {
  scene.dimension = r.integer_in(r.require(doc, "", "dimension"), "dimension", 2, 3);
  if (const Json* v = Reader::find(doc, "mode"))
    scene.mode = r.choice(*v, "mode", {"liquid", "shallow_water"}) == 0 ? SimulationMode::Liquid
                                                                          : SimulationMode::ShallowWater;
  if (scene.mode == SimulationMode::ShallowWater && scene.dimension != 2)
    r.fail("mode", "shallow_water requires dimension 2, got " + std::to_string(scene.dimension));
  const Json& domain = r.require(doc, "", "domain");
  const glm::vec3 extent = r.vector(domain, "domain", scene.dimension, double(FLT_MAX));
  for (int a = 0; a < scene.dimension; ++a)
    if (!(extent[a] > 0.0f && extent[a] <= k_max_domain_extent))
      r.fail(element("domain", size_t(a)), "must be in (0, " + format_number(k_max_domain_extent) + "], got " +
                                               format_number(extent[a]));
  scene.domain = extent;
  r.set_space(scene.dimension, extent);
}

void read_physics(const Reader& r, const Json& doc, Scene& scene) {
  const bool shallow = scene.mode == SimulationMode::ShallowWater;
  for (const NumberKey& row : k_number_keys)
    if (const Json* v = Reader::find(doc, row.key)) {
      if (shallow && row.shallow_refusal) r.fail(row.key, row.shallow_refusal);
      read_number_key(r, *v, row, scene);
    }
  if (const Json* v = Reader::find(doc, "gravity")) scene.gravity = r.scene_vector(*v, "gravity", k_max_gravity);
  if (shallow && glm::dot(scene.gravity, scene.gravity) == 0.0f)
    r.fail("gravity", "must be nonzero in shallow_water mode (|g| sets the wave speed)");

  float smallest = scene.domain.x;
  for (int a = 1; a < scene.dimension; ++a) smallest = std::min(smallest, scene.domain[a]);
  const double spacing = r.number(r.require(doc, "", "particle_spacing"), "particle_spacing");
  if (!(spacing > 0.0) || spacing > 0.5 * smallest)
    r.fail("particle_spacing", "must be in (0, " + format_number(0.5 * smallest) +
                                   "] (at most half the smallest domain extent), got " + format_number(spacing));
  scene.particle_spacing = float(spacing);

  if (const Json* v = Reader::find(doc, "rest_density")) {
    if (v->is_string()) {
      const std::string text = v->get<std::string>();
      if (text != "auto") r.fail("rest_density", "must be a number or \"auto\", got \"" + text + "\"");
    } else {
      scene.rest_density = float(r.number_in(*v, "rest_density", 1.0, 1e5));
    }
  }
  if (const Json* v = Reader::find(doc, "adaptive_time_step"))
    scene.adaptive_time_step = read_adaptive_time_step(r, *v, "adaptive_time_step");
  if (const Json* v = Reader::find(doc, "splat_format"))
    scene.splat_format = std::array{SplatFormat::Auto, SplatFormat::Rgba32f, SplatFormat::Rgba16f}
        [r.choice(*v, "splat_format", {"auto", "rgba32f", "rgba16f"})];
  if (const Json* v = Reader::find(doc, "pressure_force")) {
    if (shallow) r.fail("pressure_force", "not used in shallow_water mode");
    scene.pressure_force = r.choice(*v, "pressure_force", {"chapter", "splat_adjoint"}) == 0
                               ? PressureForce::Chapter
                               : PressureForce::SplatAdjoint;
  }
  // A scene that names the chapter's pressure, and shallow water, get the chapter's own defaults
  // for the keys they leave out: no projection (it needs the splat-adjoint pressure), its PIC share.
  if (shallow) scene.pressure_force = PressureForce::Chapter;  // not used there
  if (scene.pressure_force == PressureForce::Chapter) {
    if (!Reader::find(doc, "projection_iterations")) scene.projection_iterations = 0;
    if (!Reader::find(doc, "pic_ratio")) scene.pic_ratio = k_chapter_pic_ratio;
  }
  if (const Json* v = Reader::find(doc, "splat"))
    scene.splat = r.choice(*v, "splat", {"point_sprite", "separable"}) == 0 ? SplatMode::PointSprite
                                                                            : SplatMode::Separable;
  if (const Json* v = Reader::find(doc, "transfer")) {
    if (shallow) r.fail("transfer", "not used in shallow_water mode");
    scene.transfer = r.choice(*v, "transfer", {"pic_flip", "affine"}) == 0 ? Transfer::PicFlip : Transfer::Affine;
    if (scene.transfer == Transfer::Affine && scene.splat == SplatMode::Separable)
      r.fail("transfer", "\"affine\" needs \"splat\": \"point_sprite\" (the separable splat does not yet carry the "
                         "velocity gradient through its spreads)");
  }
  if (scene.position_correction > 0.0f && scene.splat != SplatMode::Separable)
    r.fail("position_correction", "needs \"splat\": \"separable\" (it reads the separable splat's deposit), got " +
                                      format_number(scene.position_correction));
  if (const Json* v = Reader::find(doc, "rest_depth")) {
    if (!shallow) r.fail("rest_depth", "only allowed in shallow_water mode");
    scene.rest_depth = float(r.number_in(*v, "rest_depth", 0.0, k_max_length, true));
  }
  // Steps past the chapter's regime are stable only for the twice-smoothed pressure, and only
  // accurate with the PIC blend per second (docs/physics.md, "Longer steps").
  if (scene.adaptive_time_step && scene.adaptive_time_step->acoustic_cfl > k_max_acoustic_cfl_chapter &&
      !liquid::long_step_regime(scene))
    r.fail("adaptive_time_step.acoustic_cfl",
           "above " + format_number(k_max_acoustic_cfl_chapter) +
               " needs \"pressure_force\": \"splat_adjoint\" with pic_ratio_reference_step or the projection, got " +
               format_number(scene.adaptive_time_step->acoustic_cfl));
}

void read_contents(const Reader& r, const Json& doc, Scene& scene) {
  const bool shallow = scene.mode == SimulationMode::ShallowWater;
  scene.fluid_blocks = read_array<FluidBlock>(r, doc, "fluid_blocks", read_fluid_block);
  scene.emitters = read_array<Emitter>(r, doc, "emitters", read_emitter);
  scene.obstacles = read_array<Obstacle>(r, doc, "obstacles", read_obstacle);
  // The body force is the reaction of the splat-adjoint pressure's energy (the chapter's pressure
  // force is no gradient of one); it has no term for shallow water's ground, nor does it read the
  // mesh field: bodies and static meshes are not yet in one scene (a dynamic mesh carries its own
  // distance, liquid/solver/body_shapes.h).
  const bool meshes = std::any_of(scene.obstacles.begin(), scene.obstacles.end(),
                                  [](const Obstacle& o) { return o.shape == ObstacleShape::Mesh && !o.dynamic; });
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].dynamic && (shallow || meshes || scene.pressure_force != PressureForce::SplatAdjoint))
      r.fail(element("obstacles", i) + ".dynamic",
             shallow  ? "not available in shallow_water mode"
             : meshes ? "not available in a scene with static mesh obstacles"
                      : "needs \"pressure_force\": \"splat_adjoint\" (the body force is the reaction of its energy)");
  // The correction pushes the liquid out from under a body and floats it too high (docs/physics.md,
  // "Still water that keeps its volume").
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].dynamic && scene.position_correction > 0.0f)
      r.fail(element("obstacles", i) + ".dynamic",
             "not yet with \"position_correction\" (it floats bodies 20 to 57 % high), got " +
                 format_number(scene.position_correction));
  if (!shallow && Reader::find(doc, "ground")) r.fail("ground", "only allowed in shallow_water mode");
  scene.ground = read_array<GroundHill>(r, doc, "ground", read_ground_hill);
  if (const Json* v = Reader::find(doc, "camera")) {
    if (scene.dimension != 3) r.fail("camera", "only allowed in 3D scenes (dimension 3)");
    scene.camera = read_camera(r, *v, "camera");
  }
  if (const Json* v = Reader::find(doc, "whitewater")) {
    if (shallow) r.fail("whitewater", "not available in shallow_water mode");
    scene.whitewater = read_whitewater(r, *v, "whitewater");
  }
  if (scene.fluid_blocks.empty() && scene.emitters.empty())
    r.fail("fluid_blocks", "the scene needs at least one fluid block or one emitter");
}

}  // namespace

std::span<const NumberKey> number_keys() { return k_number_keys; }

std::vector<const char*> top_level_keys() {
  std::vector<const char*> keys(std::begin(k_structured_keys), std::end(k_structured_keys));
  for (const NumberKey& row : k_number_keys) keys.push_back(row.key);
  return keys;
}

Scene read_scene(const Json& doc, const std::string& source_name) {
  Reader r(source_name);
  if (!doc.is_object()) r.fail("(document)", std::string("must be a JSON object, got ") + doc.type_name());
  r.check_keys(doc, "", top_level_keys());
  Scene scene;
  scene.name = std::filesystem::path(source_name).stem().string();
  if (const Json* v = Reader::find(doc, "name")) {
    scene.name = r.string(*v, "name");
    if (scene.name.empty()) r.fail("name", "must not be empty");
  }
  read_space(r, doc, scene);
  read_physics(r, doc, scene);
  read_contents(r, doc, scene);
  return scene;
}

}  // namespace liquid::scene_reader

namespace liquid {

bool uses_splat_adjoint_pressure(const Scene& scene) {
  return scene.mode == SimulationMode::Liquid && scene.pressure_force == PressureForce::SplatAdjoint;
}

int projection_iterations_of(const Scene& scene) {
  return scene.mode == SimulationMode::Liquid ? scene.projection_iterations : 0;
}

bool long_step_regime(const Scene& scene) {
  return uses_splat_adjoint_pressure(scene) &&
         ((scene.pic_ratio_reference_step && *scene.pic_ratio_reference_step > 0.0f) || projection_iterations_of(scene) > 0);
}

}  // namespace liquid
