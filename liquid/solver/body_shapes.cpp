#include "liquid/solver/body_shapes.h"

#include "engine/graph/transfer.h"
#include "liquid/physics/mesh.h"
#include "liquid/solver/gpu_types.h"

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {
constexpr int k_max_resolution = 128;
}

bool is_mesh_body(const Obstacle& o) { return o.dynamic && o.shape == ObstacleShape::Mesh; }

int body_shape_resolution(const Scene& scene, const SimulationSetup& setup) {
  int n = 1;
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (is_mesh_body(scene.obstacles[i]))
      n = std::max(n, int(std::ceil(2.0f * setup.bodies.at(i).shape_half_size / (0.5f * setup.cell_size))));
  return std::min(n, k_max_resolution);
}

std::vector<glm::vec4> body_shape_texels(const Scene& scene, const SimulationSetup& setup) {
  const int n = body_shape_resolution(scene, setup);
  std::vector<glm::vec4> texels(size_t(n) * n * n, glm::vec4(float(LIQUID_MESH_FAR)));
  int slot = 0;
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    if (!is_mesh_body(o)) continue;
    const float half = setup.bodies.at(i).shape_half_size, spacing = 2.0f * half / float(n);
    // The body's own frame: the mesh unturned about its centre of mass (mesh_body_in_principal_frame).
    TriangleMesh own = o.mesh;
    own.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    const PlacedMesh placed(own, glm::vec3(0.0f), 2.0f * half);
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const glm::vec3 p = -glm::vec3(half) + (glm::vec3(x, y, z) + 0.5f) * spacing;
          texels[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * z)][slot] = placed.distance(p);
        }
    ++slot;
  }
  return texels;
}

engine::vk::Image make_body_shapes(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup) {
  const uint32_t n = uint32_t(body_shape_resolution(scene, setup));
  engine::vk::Image image(context,
                          {engine::vk::ImageKind::Image3D, n, n, n, k_body_shapes_format,
                           VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                          "liquid.body_shapes");
  const std::vector<glm::vec4> texels = body_shape_texels(scene, setup);
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
