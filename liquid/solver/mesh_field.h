// Mesh obstacles voxelized by the rasterizer into the mesh field: one grid image (the grid's
// layout, RGBA16F) holding each mesh's signed distance (m, negative inside) in its own channel,
// which the grid, pressure and particle passes sample as they evaluate an analytic obstacle's
// (common.glsl, MESH_FIELD). Three passes, redone in a step when a mesh's placement changed:
//   liquid.mesh_inside  each triangle drawn, looking along z, into every slice of the mesh's z
//                       range; a fragment counts +-1 (its facing) where the surface lies above the
//                       cell centre, added by blending: non-zero inside (mesh_inside.frag).
//   liquid.mesh_band    per triangle and slice within the band, the rectangle of cells within the
//                       band of it: the exact point-triangle distance, MIN-blended (mesh_band.frag).
//   liquid.mesh_field   a full-screen grid pass: the signed distance, clamped to the band.
// The band is obstacle_band + LIQUID_MESH_FIELD_MARGIN_CELLS cells: what the obstacle density and
// its normal read. Graphics pipeline only; every 3D path (layered by the vertex or geometry
// shader, or the atlas's tiles). In 2D the grid's cells lie at z = 0: the mesh's cross-section.
// Shaders: shaders/liquid/solver/mesh_raster.vert, mesh_raster.geom, mesh_inside.frag,
// mesh_band.frag, mesh_field.frag.
#pragma once

#include "engine/passes/bindings.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "engine/vk/uniform_arena.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/grid_layout.h"
#include "liquid/solver/gpu_types.h"
#include "liquid/solver/images.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace liquid {

constexpr VkFormat k_mesh_field_format = VK_FORMAT_R32G32B32A32_SFLOAT;

// Whether the scene has mesh obstacles (its passes then take the MESH_FIELD variants).
bool has_mesh_obstacles(const Scene& scene);

// A mesh's triangles as a texture (RGBA32F, LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH wide): the corners
// of triangle t, in the mesh's frame, at texels 3t, 3t + 1 and 3t + 2, row by row.
engine::vk::Image mesh_triangle_texture(engine::vk::Context& context, const TriangleMesh& mesh, const std::string& name);

// For the passes that sample the field (grid, pressure, particle): the shader variant, the
// pipeline's binding, and the pass's read of `field` (nothing when it is invalid: no meshes).
inline std::span<const uint32_t> mesh_variant(bool meshes, std::span<const uint32_t> plain,
                                              std::span<const uint32_t> with_field) {
  return meshes ? with_field : plain;
}
void add_mesh_field_binding(bool meshes, std::vector<engine::vk::DescriptorBinding>& bindings);
void bind_mesh_field(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle field,
                     const engine::vk::Sampler& linear);

class MeshField {
 public:
  MeshField(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup, const GridLayout& layout,
            const std::vector<int32_t>& specialization);

  // The field as it is now and the meshes' triangles, imported into `graph` (once per graph, before update()).
  ImageHandle import(engine::graph::RenderGraph& graph);
  // Declares the three passes when the meshes' placements (`obstacles`' meshes at `poses`) differ
  // from the last voxelization's, and returns the field's latest version.
  ImageHandle update(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                     const std::vector<Obstacle>& obstacles, const std::vector<ObstaclePose>& poses, ImageHandle field);
  // Forgets the last voxelization, so the next update() redoes it (its graph was not executed).
  void invalidate() { voxelized_.reset(); }
  // The field downloaded, cell (x, y, z) at x + nx (y + ny z), one channel per mesh (blocking: no
  // frame of the node in flight).
  std::vector<glm::vec4> read(engine::vk::Context& context);
  // How many voxelizations update() has declared (tests and tools).
  int voxelizations() const { return voxelizations_; }
  float band() const { return band_; }

 private:
  struct Mesh {
    size_t obstacle = 0;          // index in the scene's obstacles
    engine::vk::Image triangles;  // RGBA32F, 3 texels per triangle (the mesh's frame)
    uint32_t triangle_count = 0;
  };
  // The inside or the band pass: every mesh's triangles drawn `instances[k]` times into `target`,
  // cleared to `clear` first and blended (additive or MIN, the pipeline's).
  struct RasterPass {
    const char* name;
    const engine::vk::GraphicsPipeline* pipeline;
    uint32_t vertices_per_triangle;
    float clear;
  };
  ImageHandle add_raster_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                              const RasterPass& pass, ImageHandle target, const std::vector<gpu::MeshRasterPush>& pushes,
                              const std::vector<uint32_t>& instances) const;

  GridLayout layout_;
  float cell_size_ = 0.0f;
  float band_ = 0.0f;  // m
  std::vector<Mesh> meshes_;
  std::vector<ImageHandle> triangle_handles_;  // the last import()'s
  engine::vk::GraphicsPipeline inside_, band_pipeline_, field_pipeline_;
  engine::vk::Sampler nearest_;
  engine::vk::Image field_;
  std::optional<std::vector<glm::mat4>> voxelized_;  // the placements of the field's contents
  int voxelizations_ = 0;
};

}  // namespace liquid
