// The host's own pass, recorded with plain Vulkan outside the liquid's render graph: it clears its
// HDR colour target and its reversed-Z depth (to 0, the far plane) and draws its floor and its paddle
// (host_mesh.h, from its own vertex and index buffers) in linear radiance. It takes each target from the layout and last access the graph left it in
// (engine::vk::Image::sync_state()) and records where it leaves them, so the graph's first pass on
// them next waits for exactly this pass.
#pragma once

#include "host_mesh.h"
#include "host_vulkan.h"
#include "shaders/host_limits.h"

#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

#include <glm/glm.hpp>

class ScenePass {
 public:
  static constexpr VkFormat k_color_format = VK_FORMAT_R16G16B16A16_SFLOAT;  // linear HDR
  static constexpr VkFormat k_depth_format = VK_FORMAT_D32_SFLOAT;           // reversed Z

  static constexpr size_t k_max_vertices = HOST_MAX_VERTICES;               // scene.vert's uniform array

  // Uploads both meshes into the host's own buffers (at most k_max_vertices vertices in all).
  ScenePass(engine::vk::Context& context, const HostVulkan& vulkan, const HostMesh& floor, const HostMesh& paddle);

  // Each mesh drawn placed by its model matrix.
  void record(VkCommandBuffer cmd, engine::vk::Image& color, engine::vk::Image& depth, const glm::mat4& view_projection,
              const glm::mat4& floor_model, const glm::mat4& paddle_model) const;

 private:
  // Where a mesh lies in the shared buffers.
  struct Range {
    uint32_t first_index = 0, index_count = 0;
    int32_t vertex_offset = 0;
  };
  struct Buffers;  // the meshes laid end to end, before upload

  ScenePass(engine::vk::Context& context, const HostVulkan& vulkan, const Buffers& buffers);

  engine::vk::GraphicsPipeline pipeline_;
  HostBuffer vertices_;  // uniform buffer, scene.vert's HostVertices
  HostBuffer indices_;   // index buffer
  Range floor_, paddle_;
};
