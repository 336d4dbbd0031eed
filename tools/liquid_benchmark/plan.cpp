// The plan: the paper's configurations and the 2D and 3D scaling points, with the scene changes
// each needs, and the --only selection.
#include "tools/liquid_benchmark/plan.h"

#include "liquid/physics/setup.h"
#include "liquid/scene/override.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tools::benchmark {

const char* mode_name(Mode mode) { return mode == Mode::Simulation ? "sim" : "sim+render"; }

std::string view_name(const Configuration& c) {
  if (c.mode == Mode::Simulation) return "none";
  if (c.scene.mode == liquid::SimulationMode::ShallowWater) return "height_field";
  return c.scene.dimension == 3 ? "raymarch" : "view2d";
}

std::string grid_label(glm::ivec3 g) {
  return g.z > 1 ? std::to_string(g.x) + "x" + std::to_string(g.y) + "x" + std::to_string(g.z)
                 : std::to_string(g.x) + "x" + std::to_string(g.y);
}

namespace {

// The jet of paper_3d needs ~3 s of simulated time (~17,000 steps) to add its 26,720 particles,
// but the paper's 35 fps is for the scene at capacity (~125k). So the emitter's particles are
// placed up front as a cube of liquid near the top of the domain, above the spheres: the
// benchmark then runs the full count from the first frame.
std::string fill_emitters_up_front(liquid::Scene& scene) {
  int capacity = 0;
  for (const liquid::Emitter& e : scene.emitters) capacity += e.capacity;
  if (capacity == 0 || scene.dimension != 3) return "";
  scene.emitters.clear();
  const int side = int(std::lround(std::cbrt(double(capacity))));
  const float s = scene.particle_spacing;
  // (side + 0.5) spacings hold exactly `side` lattice points whatever the float rounding.
  const float edge = (float(side) + 0.5f) * s;
  const glm::vec3 d = scene.domain;
  const float top = d.y - 0.05f * d.y;
  scene.fluid_blocks.push_back({glm::vec3(0.5f * (d.x - edge), top - edge, 0.5f * (d.z - edge)),
                                glm::vec3(0.5f * (d.x + edge), top, 0.5f * (d.z + edge)), glm::vec3(0.0f)});
  return "the emitter's " + std::to_string(capacity) + " particles are replaced by a " + std::to_string(side) +
         "^3 block (" + std::to_string(side * side * side) +
         " particles) above the spheres, so the scene runs at capacity from the first frame";
}

// A 2D scene with one block of about `count` particles on its lattice (the block's shape kept).
liquid::Scene with_particle_count(liquid::Scene scene, int count) {
  if (scene.fluid_blocks.empty()) throw std::invalid_argument(scene.name + ": the scaling runs need a fluid block");
  scene.fluid_blocks.resize(1);
  const glm::vec3 extent = scene.fluid_blocks[0].max - scene.fluid_blocks[0].min;
  scene.particle_spacing = float(std::sqrt(double(extent.x) * extent.y / count));
  return scene;
}

// The wall margin follows the spacing roughly as in the paper_2d_* files (0.4 spacings, in cells,
// at most 0.45), so the lattice's outer particles start inside the margin.
void set_wall_margin(liquid::Scene& scene) {
  const double longest = std::max(scene.domain.x, scene.domain.y);
  const double cell = longest / scene.grid_resolution.value_or(256);
  scene.wall_margin_cells = float(std::min(0.45, 0.4 * scene.particle_spacing / cell));
}

liquid::Scene load_named_scene(const Options& o, const std::string& name) {
  return liquid::load_scene(o.scenes_dir / (name + ".json"));
}

Configuration make_configuration(std::string name, std::string group, std::string scene_name, liquid::Scene scene,
                                 Mode mode, int frames) {
  Configuration c;
  c.name = std::move(name);
  c.group = std::move(group);
  c.scene_name = std::move(scene_name);
  c.note = fill_emitters_up_front(scene);
  c.scene = std::move(scene);
  c.mode = mode;
  c.timed_frames = frames;
  if (mode == Mode::SimulationAndRender && c.group == "paper") c.paper = paper_figure(c.scene_name);
  // The CPU-side setup validates the scene now, before any GPU work (the node checks it again
  // against the device's real limits).
  const liquid::SimulationSetup setup = liquid::make_setup(c.scene, liquid::DeviceLimits{});
  c.particles = setup.initial_particles;
  c.grid = setup.grid_cells;
  return c;
}

// The scene of `name` with its "splat" key set to `mode` through the scene's JSON before it is
// read (as liquid_capture's --set does), so the reader checks the value like one in the file.
// When this build's scenes have no such key, the chapter's point_sprite is the file as it is and
// any other mode is nothing.
std::optional<liquid::Scene> scene_in_splat_mode(const Options& o, const std::string& name, const std::string& mode) {
  const std::filesystem::path file = o.scenes_dir / (name + ".json");
  const std::string set = "splat=" + mode;
  try {
    return liquid::parse_scene(liquid::scene_document(file, {liquid::parse_scene_override(set)}),
                               file.string() + " with " + set);
  } catch (const liquid::SceneError& e) {
    const std::string message = e.what();
    const std::string unknown = ": splat: unknown key";
    const bool key_unknown = message.size() >= unknown.size() &&
                             message.compare(message.size() - unknown.size(), unknown.size(), unknown) == 0;
    if (!key_unknown) throw;
    if (mode == k_default_splat_mode) return load_named_scene(o, name);
    return std::nullopt;
  }
}

// "paper_2d_64k/sim" for the chapter's point sprites, "paper_2d_64k:separable/sim" for another mode.
std::string paper_label(const std::string& name, const std::string& mode, Mode m) {
  return name + (mode == k_default_splat_mode ? "" : ":" + mode) + "/" + mode_name(m);
}

std::vector<Configuration> paper_configurations(const Options& o, std::vector<Skipped>& skipped) {
  std::vector<Configuration> out;
  for (const char* name : {"paper_2d_16k", "paper_2d_32k", "paper_2d_64k", "shallow_water", "paper_3d"}) {
    const bool paper_scene = std::string(name).rfind("paper_", 0) == 0;
    const std::vector<std::string> modes = paper_scene ? o.splat_modes : std::vector<std::string>{""};
    for (const std::string& splat : modes) {
      std::optional<liquid::Scene> scene =
          splat.empty() ? load_named_scene(o, name) : scene_in_splat_mode(o, name, splat);
      if (!scene) {
        const std::string reason = "this build's scenes have no \"splat\" key, so only the chapter's " +
                                   std::string(k_default_splat_mode) + " splat runs";
        if (o.splat_modes_given) throw std::invalid_argument("--splat-modes " + splat + ": " + reason);
        if (std::none_of(skipped.begin(), skipped.end(), [&](const Skipped& s) { return s.name == "paper_*:" + splat; }))
          skipped.push_back({"paper_*:" + splat, reason});
        continue;
      }
      for (Mode mode : {Mode::Simulation, Mode::SimulationAndRender}) {
        const std::string label = paper_label(name, splat.empty() ? k_default_splat_mode : splat, mode);
        if (scene->dimension == 2 || o.paths_3d.empty()) {
          out.push_back(make_configuration(label, "paper", name, *scene, mode, o.runs));
          out.back().splat_mode = splat;
          continue;
        }
        for (liquid::GridPath path : o.paths_3d) {  // the path as a configuration axis
          out.push_back(make_configuration(label + "/" + liquid::grid_path_name(path), "paper", name, *scene, mode, o.runs));
          out.back().grid_path = path;
          out.back().splat_mode = splat;
        }
      }
    }
  }
  return out;
}

// liquid_viewer on the dam breaks as a user opens them (the file as it is, one step per frame,
// the panel shown): its frame rate at the benchmark's frame size.
std::vector<Configuration> viewer_configurations(const Options& o) {
  std::vector<Configuration> out;
  for (const char* name : {"dam_break_2d", "dam_break_3d"}) {
    Configuration c;
    c.name = std::string("viewer/") + name;
    c.group = "viewer";
    c.scene_name = name;
    c.scene_file = o.scenes_dir / (std::string(name) + ".json");
    c.scene = liquid::load_scene(c.scene_file);
    c.mode = Mode::SimulationAndRender;
    c.timed_frames = o.viewer_frames > 0 ? o.viewer_frames : c.scene.dimension == 3 ? 20 : 60;
    c.note = "liquid_viewer " + c.scene_file.filename().string() + ", its frame rate over the frames after the first";
    const liquid::SimulationSetup setup = liquid::make_setup(c.scene, liquid::DeviceLimits{});
    c.particles = setup.initial_particles;
    c.grid = setup.grid_cells;
    out.push_back(std::move(c));
  }
  return out;
}

// paper_3d's raymarch composited into a host's targets of each format the library takes, RGBA8 +
// D32 first (the path before other formats existed), with the library's camera and no FXAA.
std::vector<Configuration> composite_configurations(const Options& o) {
  struct Target {
    const char* label;
    VkFormat color, depth;
  };
  const Target targets[] = {
      {"rgba8_unorm+d32", VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT},
      {"bgra8_srgb+d32", VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_D32_SFLOAT},
      {"a2b10g10r10+d32", VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_D32_SFLOAT},
      {"rgba16f+d32", VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT},
      {"b10g11r11+d32", VK_FORMAT_B10G11R11_UFLOAT_PACK32, VK_FORMAT_D32_SFLOAT},
      {"rgba8_unorm+d24s8", VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D24_UNORM_S8_UINT},
      {"rgba8_unorm+d32s8", VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT_S8_UINT},
  };
  std::vector<Configuration> out;
  for (const Target& t : targets) {
    Configuration c = make_configuration(std::string("composite/") + t.label, "composite", "paper_3d",
                                         load_named_scene(o, "paper_3d"), Mode::SimulationAndRender, o.runs);
    c.composite_color = t.color;
    c.composite_depth = t.depth;
    c.note = "paper_3d composited into host targets (library camera, FXAA off)";
    out.push_back(std::move(c));
  }
  return out;
}

// A closed torus in the xz plane (its hole along y) about the origin, as tools/make_torus_obj.py
// writes it: major radius R, tube radius r, major x minor segments of two triangles.
liquid::TriangleMesh torus_mesh(float R, float r, int major, int minor) {
  liquid::TriangleMesh mesh;
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const float u = 2.0f * float(M_PI) * float(i) / float(major), v = 2.0f * float(M_PI) * float(j) / float(minor);
      const float ring = R + r * std::cos(v);
      mesh.vertices.push_back({ring * std::cos(u), r * std::sin(v), ring * std::sin(u)});
    }
  const auto index = [&](int i, int j) { return uint32_t((i % major) * minor + (j % minor)); };
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      mesh.indices.insert(mesh.indices.end(), {a, d, c, a, c, b});
    }
  return mesh;
}

// Mesh obstacles (liquid/solver/mesh_field.h), simulation only: paper_3d with a torus of 10,000
// triangles in its pool, as tools/mesh_voxelization_cost.sh places it, moving (its field made
// again every step: resampled from its reference field) and standing still (made once: sampling
// the field's cost).
std::vector<Configuration> mesh_configurations(const Options& o) {
  liquid::Obstacle torus;
  torus.shape = liquid::ObstacleShape::Mesh;
  torus.mesh = torus_mesh(0.1f, 0.035f, 100, 50);
  torus.mesh.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  torus.mesh.scale = 1.5f;
  torus.center = glm::vec3(0.3f, 0.1f, 0.6f);
  const size_t triangles = torus.mesh.indices.size() / 3;
  std::vector<Configuration> out;
  for (const bool moving : {true, false}) {
    liquid::Scene scene = load_named_scene(o, "paper_3d");
    torus.velocity = glm::vec3(moving ? 0.5f : 0.0f, 0.0f, 0.0f);
    scene.obstacles.push_back(torus);
    const std::string state = moving ? "moving" : "still";
    std::vector<std::optional<liquid::GridPath>> paths(o.paths_3d.begin(), o.paths_3d.end());
    if (paths.empty()) paths.push_back(std::nullopt);
    for (const std::optional<liquid::GridPath>& path : paths) {
      Configuration c = make_configuration("mesh/torus_" + std::to_string(triangles) + "_tri/" + state + "/sim" +
                                               (path ? std::string("/") + liquid::grid_path_name(*path) : std::string()),
                                           "mesh", "paper_3d", scene, Mode::Simulation, o.runs);
      c.grid_path = path;
      c.note = "paper_3d with a torus of " + std::to_string(triangles) + " triangles in its pool, grid " +
               grid_label(c.grid) + ", " +
               (moving ? "moving at 0.5 m/s (its field made every step)" : "standing still (its field made once)") + "; " +
               c.note;
      out.push_back(std::move(c));
    }
  }
  return out;
}

// The secondary particles' cost (liquid/solver/whitewater.h), simulation only: the shipped 3D dam
// break hitting a box with "whitewater" as shipped (two slots per particle) and the same scene
// without it, whose steps' ratio is what the whitewater adds.
std::vector<Configuration> whitewater_configurations(const Options& o) {
  std::vector<Configuration> out;
  for (const bool on : {false, true}) {
    liquid::Scene scene = load_named_scene(o, "dam_break_3d_whitewater");
    const int slots = scene.whitewater ? scene.whitewater->slots_per_particle : 0;
    if (!on) scene.whitewater.reset();
    Configuration c = make_configuration(std::string("whitewater/dam_break_3d/") + (on ? "on" : "off") + "/sim",
                                         "whitewater", "dam_break_3d_whitewater", scene, Mode::Simulation, o.runs);
    c.note = "dam_break_3d_whitewater, " +
             (on ? std::to_string(slots) + " secondary-particle slots per particle" : std::string("whitewater off"));
    out.push_back(std::move(c));
  }
  return out;
}

// Simulation only, from paper_2d_64k: particle count 16k..256k on its 256^2 grid, then grid
// 128^2..1024^2 at 64k particles (the 256^2 point is shared with the first curve).
std::vector<Configuration> scaling_configurations(const Options& o) {
  const std::string base_name = "paper_2d_64k";
  const liquid::Scene base = load_named_scene(o, base_name);
  std::vector<Configuration> out;
  for (int k : {16, 32, 64, 128, 256}) {
    liquid::Scene scene = with_particle_count(base, k * 1000);
    scene.grid_resolution = 256;
    set_wall_margin(scene);
    out.push_back(make_configuration("scaling/particles/" + std::to_string(k) + "k", "scaling", base_name, scene,
                                     Mode::Simulation, o.scaling_runs));
  }
  for (int resolution : {128, 512, 1024}) {
    liquid::Scene scene = with_particle_count(base, 64 * 1000);
    scene.grid_resolution = resolution;
    set_wall_margin(scene);
    out.push_back(make_configuration("scaling/grid/" + std::to_string(resolution), "scaling", base_name, scene,
                                     Mode::Simulation, o.scaling_runs));
  }
  for (Configuration& c : out)
    c.note = "paper_2d_64k with one block of " + std::to_string(c.particles) + " particles on a " +
             std::to_string(c.grid.x) + "^2 grid (spacing " + std::to_string(c.scene.particle_spacing) + " m)";
  return out;
}

// paper_3d with the separable splat (the fast 3D path), scaled by `factor` along each axis at the
// same spacing per cell: spacing, cell and step divided by it, the emitter's particles (placed up
// front) multiplied by its cube, so the count grows as factor^3 on a grid of 96 factor cells a side.
liquid::Scene scaled_3d(liquid::Scene scene, double factor) {
  scene.splat = liquid::SplatMode::Separable;
  scene.particle_spacing = float(scene.particle_spacing / factor);
  scene.grid_resolution = int(std::lround(scene.grid_resolution.value_or(96) * factor));
  scene.time_step = float(scene.time_step / factor);
  for (liquid::Emitter& e : scene.emitters) e.capacity = int(std::lround(e.capacity * factor * factor * factor));
  return scene;
}

// Simulation only, from paper_3d with the separable splat: 125k to 1M particles, the grid growing
// as N^(1/3) (96^3 to 192^3); each point also reports the device memory it held.
std::vector<Configuration> scaling_3d_configurations(const Options& o) {
  const std::string base_name = "paper_3d";
  const liquid::Scene base = load_named_scene(o, base_name);
  std::vector<std::optional<liquid::GridPath>> paths(o.paths_3d.begin(), o.paths_3d.end());
  if (paths.empty()) paths.push_back(std::nullopt);
  std::vector<Configuration> out;
  for (const int k : {125, 250, 500, 1000}) {
    const double factor = std::cbrt(k / 125.0);
    for (const std::optional<liquid::GridPath>& path : paths) {
      Configuration c = make_configuration(
          "scaling3d/particles/" + (k < 1000 ? std::to_string(k) + "k" : std::to_string(k / 1000) + "M") +
              (path ? std::string("/") + liquid::grid_path_name(*path) : std::string()),
          "scaling3d", base_name, scaled_3d(base, factor), Mode::Simulation, o.scaling_runs);
      c.grid_path = path;
      c.splat_mode = "separable";
      c.note = "paper_3d, separable splat, " + std::to_string(c.particles) + " particles on a " + grid_label(c.grid) +
               " grid (spacing " + std::to_string(c.scene.particle_spacing) + " m, step " +
               std::to_string(c.scene.time_step) + " s); " + c.note;
      out.push_back(std::move(c));
    }
  }
  return out;
}

// A --only value selects the configuration of that exact name, else every name containing it
// ("paper_2d_64k/sim" is one configuration, "paper_2d" six).
bool matches(const std::string& name, const std::string& pattern, const std::vector<Configuration>& all) {
  const bool exact_exists =
      std::any_of(all.begin(), all.end(), [&](const Configuration& c) { return c.name == pattern; });
  return exact_exists ? name == pattern : name.find(pattern) != std::string::npos;
}

}  // namespace

Plan make_plan(const Options& o) {
  for (const std::string& mode : o.splat_modes)
    if (mode.empty() || mode.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      throw std::invalid_argument("--splat-modes: '" + mode + "' is not a splat mode name (lower case, digits, _)");
  for (size_t i = 0; i < o.splat_modes.size(); ++i)
    if (std::count(o.splat_modes.begin(), o.splat_modes.begin() + i, o.splat_modes[i]))
      throw std::invalid_argument("--splat-modes: '" + o.splat_modes[i] + "' is given twice");
  Plan result;
  std::vector<Configuration> all;
  if (!o.scaling_only) all = paper_configurations(o, result.skipped);
  if (!o.no_scaling) {
    auto scaling = scaling_configurations(o);
    all.insert(all.end(), scaling.begin(), scaling.end());
    auto scaling_3d = scaling_3d_configurations(o);
    all.insert(all.end(), scaling_3d.begin(), scaling_3d.end());
  }
  if (!o.scaling_only) {
    auto meshes = mesh_configurations(o);
    all.insert(all.end(), meshes.begin(), meshes.end());
    auto whitewater = whitewater_configurations(o);
    all.insert(all.end(), whitewater.begin(), whitewater.end());
  }
  if (o.composite && !o.scaling_only) {
    auto composite = composite_configurations(o);
    all.insert(all.end(), composite.begin(), composite.end());
  }
  if (o.viewer && !o.scaling_only) {
    auto viewer = viewer_configurations(o);
    all.insert(all.end(), viewer.begin(), viewer.end());
  }
  for (const std::string& s : o.only)
    if (std::none_of(all.begin(), all.end(), [&](const Configuration& c) { return matches(c.name, s, all); })) {
      std::string why = "--only " + s + ": matches no configuration (see --list)";
      for (const Skipped& k : result.skipped) why += "; skipped " + k.name + ": " + k.reason;
      throw std::invalid_argument(why);
    }
  std::vector<bool> keep(all.size(), o.only.empty());
  for (size_t i = 0; i < all.size(); ++i)
    for (const std::string& s : o.only) keep[i] = keep[i] || matches(all[i].name, s, all);
  for (size_t i = 0; i < all.size(); ++i)
    if (keep[i]) result.configurations.push_back(std::move(all[i]));
  return result;
}

}  // namespace tools::benchmark
