#include "liquid/solver/body_shapes.h"

#include "engine/graph/render_graph.h"
#include "engine/graph/transfer.h"
#include "engine/vk/commands.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/solver/gpu_types.h"
#include "liquid/solver/mesh_field.h"
#include "liquid/solver/specialization.h"
#include "liquid/solver/uniforms.h"

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {
constexpr int k_max_resolution = 128;

// Dynamic mesh `o` alone, unturned about its centre of mass, at the centre of a cube of `n` cells
// a side and `half` metres half a side, as a scene and setup of the solver's (copied from the
// node's, for its tables and constants) that the mesh field voxelizes: the cube's cells are the
// texture's texels. Its band reaches a cell past the kernel of the node's grid: as far as the passes
// that read a body's distance look (its kernel share and its force's differences).
std::pair<Scene, SimulationSetup> cube_of(const Scene& scene, const SimulationSetup& setup, const Obstacle& o, int n,
                                          float half) {
  Scene cube = scene;
  cube.dimension = 3;
  cube.domain = glm::vec3(2.0f * half);
  cube.grid_resolution = n;
  cube.emitters.clear();
  Obstacle mesh = o;
  mesh.dynamic = false;
  mesh.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  mesh.mesh.rotation = mesh.rotation;
  mesh.center = glm::vec3(half);
  mesh.velocity = mesh.angular_velocity = glm::vec3(0.0f);
  cube.obstacles = {mesh};
  SimulationSetup cube_setup = setup;
  cube_setup.dimension = 3;
  cube_setup.domain = cube.domain;
  cube_setup.grid_cells = glm::ivec3(n);
  cube_setup.cell_size = 2.0f * half / float(n);
  cube_setup.obstacle_band = (setup.kernel_radius_cells + 1.0f) * setup.cell_size;
  cube_setup.bodies = {BodyConstants{}};
  return {cube, cube_setup};
}

// Channel 0 of the mesh field of `cube` (its one mesh), voxelized by the rasterizer on `path`.
std::vector<float> voxelize_cube(engine::vk::Context& context, const Scene& cube, const SimulationSetup& setup,
                                 GridPath path) {
  const GridLayout layout(3, setup.grid_cells, path);
  MeshField field(context, cube, setup, layout, scene_specialization(cube, setup));
  StepInputs step;
  step.obstacle_poses = {ObstaclePose{cube.obstacles[0].center, {}, cube.obstacles[0].rotation, {}}};
  gpu::SolverUniforms u = make_uniforms(cube, setup, step);
  u.atlas_columns = layout.tiles.x;
  u.atlas_rows = layout.tiles.y;
  engine::vk::UniformArena arena(context, engine::vk::UniformArena::frame_bytes({sizeof(gpu::SolverUniforms)}), 1);
  arena.begin_frame();
  const engine::vk::UniformSlice slice = arena.push(u);
  engine::graph::RenderGraph graph(&context);
  const engine::graph::ImageHandle imported = field.import(graph);
  field.update(graph, slice, cube.obstacles, step.obstacle_poses, imported);
  graph.compile();
  engine::vk::CommandBuffer cmd(context);
  graph.execute(cmd.begin());
  cmd.submit_and_wait();
  const std::vector<glm::vec4> texels = field.read(context);
  std::vector<float> distance(texels.size());
  std::transform(texels.begin(), texels.end(), distance.begin(), [](const glm::vec4& t) { return t.x; });
  return distance;
}
}  // namespace

bool is_mesh_body(const Obstacle& o) { return o.dynamic && o.shape == ObstacleShape::Mesh; }

int body_shape_resolution(const Scene& scene, const SimulationSetup& setup) {
  int n = 1;
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (is_mesh_body(scene.obstacles[i]))
      n = std::max(n, int(std::ceil(2.0f * setup.bodies.at(i).shape_half_size / (0.5f * setup.cell_size))));
  return std::min(n, k_max_resolution);
}

engine::vk::Image make_body_shapes(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup,
                                   GridPath path) {
  const int n = body_shape_resolution(scene, setup);
  std::vector<glm::vec4> texels(size_t(n) * n * n, glm::vec4(float(LIQUID_MESH_FAR)));
  int slot = 0;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (!is_mesh_body(scene.obstacles[i])) continue;
    const auto [cube, cube_setup] = cube_of(scene, setup, scene.obstacles[i], n, setup.bodies.at(i).shape_half_size);
    const std::vector<float> distance = voxelize_cube(context, cube, cube_setup, path);
    for (size_t t = 0; t < texels.size(); ++t) texels[t][slot] = distance[t];
    ++slot;
  }
  engine::vk::Image image(context,
                          {engine::vk::ImageKind::Image3D, uint32_t(n), uint32_t(n), uint32_t(n), k_body_shapes_format,
                           VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                          "liquid.body_shapes");  // (a test reads it back)
  engine::graph::upload_image(context, image, std::as_bytes(std::span(texels)));
  return image;
}

void add_body_shapes_binding(std::vector<engine::vk::DescriptorBinding>& bindings, VkShaderStageFlags stages) {
  bindings.push_back({LIQUID_BINDING_BODY_SHAPES, DescriptorKind::SampledImage, stages});
}

void bind_body_shapes(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle shapes,
                      const engine::vk::Sampler& linear) {
  bindings.bind_image(builder, LIQUID_BINDING_BODY_SHAPES, shapes, linear.handle());
}

}  // namespace liquid
