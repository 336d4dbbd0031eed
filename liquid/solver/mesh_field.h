// Mesh obstacles voxelized by the rasterizer into the mesh field: one grid image (the grid's
// layout, RGBA32F) holding each mesh's signed distance (m, negative inside) in its own channel,
// which the grid, pressure and particle passes sample as they evaluate an analytic obstacle's
// (common.glsl, MESH_FIELD). Redone in a step when a mesh's placement changed, and only over each
// mesh's box (the cells within the band of its bounds; the field holds the band outside every box):
//   liquid.mesh_inside  each triangle drawn, looking along z, into the slices whose span between
//                       cell centres it crosses: +-1 by its facing, added by blending
//                       (mesh_inside.frag). The field pass sums them from a cell up: non-zero inside.
//   liquid.mesh_seed    per triangle and slice within LIQUID_MESH_SEED_CELLS (1.5 cells) of it, a
//                       triangle holding the cells within that of its part in the slice: the exact
//                       closest point, the closest kept by the depth test (mesh_seed.frag).
//   liquid.mesh_spread  a jump flood over the box (full-screen passes cut to it by the scissor):
//                       each cell takes the closest to it of the points held by the 27 cells `step`
//                       apart around it, steps halving to 1 (mesh_spread.frag).
//   liquid.mesh_field   one more step of 1, then the distance, clamped to the band and signed by the
//                       counts, MIN-blended into the mesh's channel.
// The band is obstacle_band + LIQUID_MESH_FIELD_MARGIN_CELLS cells: what the obstacle density and
// its normal read. Within the seed band the distance is exact (where the grid pass reads the
// normal); beyond, it is the distance to the closest of the seeds' points, at most about a tenth of
// a cell over the exact one where the closest surface point lies between them
// (docs/lavapipe-performance.md, "Mesh obstacles"). Graphics pipeline only; every 3D path (layered
// by the vertex or geometry shader, or the atlas's tiles). In 2D the grid's cells lie at z = 0: the
// mesh's cross-section. The seed, spread and field passes run once per mesh.
// In 3D a mesh whose box fits in the grid (a cell to spare) with the mesh placed at the grid's
// centre is voxelized so once, into its own reference field (R32F, grid-sized) at that reference
// placement, and again only when its scale changes; at each pose,
//   liquid.mesh_resample  over the mesh's box: the reference read trilinearly where the same point
//                         of the mesh lies in the reference placement (mesh_resample.frag),
//                         MIN-blended into the mesh's channel.
// Moving and turning keep distances, so this is the field of the pose up to the interpolation
// between the reference's cells (exact where the pose is the reference's shifted by whole cells).
// A mesh too large for that is voxelized at every pose as above. Shaders:
// shaders/liquid/solver/mesh_raster.vert, mesh_raster.geom, mesh_inside.frag, mesh_seed.frag,
// mesh_spread.frag, mesh_resample.frag.
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
#include <span>
#include <utility>
#include <vector>

namespace liquid {

constexpr VkFormat k_mesh_field_format = VK_FORMAT_R32G32B32A32_SFLOAT;

// Whether the scene has static mesh obstacles (its passes then take the MESH_FIELD variants); a
// dynamic mesh is not in the field, it carries its own distance (liquid/solver/body_shapes.h).
bool has_mesh_obstacles(const Scene& scene);

// A mesh's triangles as a texture (RGBA32F, LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH wide): the corners
// of triangle t, in the mesh's frame, at texels 3t, 3t + 1 and 3t + 2, row by row.
engine::vk::Image mesh_triangle_texture(engine::vk::Context& context, const TriangleMesh& mesh, const std::string& name);

// For the passes that sample the field (grid, pressure, particle; the 2D view): the pipeline's
// binding (`meshes`: the scene has some), and the pass's read of `field` (nothing when it is
// invalid: no meshes).
void add_mesh_field_binding(bool meshes, std::vector<engine::vk::DescriptorBinding>& bindings);
void bind_mesh_field(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle field,
                     const engine::vk::Sampler& linear);

// A mesh's box: the cells [min, max) within the band of its bounds, clamped to the grid.
struct MeshBox {
  glm::ivec3 min{0}, max{0};
};
// The box's rectangles in the grid's render target (the rectangle and the slices, one per slice's
// tile in the atlas): for vkCmdClearAttachments, and as the scissor and instances of a box pass.
std::vector<VkClearRect> mesh_box_rects(const GridLayout& layout, const MeshBox& box);

class MeshField {
 public:
  MeshField(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup, const GridLayout& layout,
            const std::vector<int32_t>& specialization);

  // The field as it is now and the meshes' triangles, imported into `graph` (once per graph, before update()).
  ImageHandle import(engine::graph::RenderGraph& graph);
  // Declares the voxelization's passes when the meshes' placements (`obstacles`' meshes at `poses`) differ
  // from the last voxelization's, and returns the field's latest version.
  ImageHandle update(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                     const std::vector<Obstacle>& obstacles, const std::vector<ObstaclePose>& poses, ImageHandle field);
  // Forgets the last voxelization, so the next update() redoes it (its graph was not executed: the
  // field still holds the boxes before it, and the references what they held, or nothing).
  void invalidate();
  // The field downloaded, cell (x, y, z) at x + nx (y + ny z), one channel per mesh (blocking: no
  // frame of the node in flight).
  std::vector<glm::vec4> read(engine::vk::Context& context);
  // How many new fields update() has declared, and of those how many voxelized a mesh's triangles
  // (its reference, or its field at the pose) rather than resampling every mesh (tests and tools).
  int voxelizations() const { return voxelizations_; }
  int triangle_voxelizations() const { return triangle_voxelizations_; }
  // Whether mesh `mesh` (in scene order among the meshes) has a reference field, resampled at each pose.
  bool resampled(size_t mesh) const { return meshes_.at(mesh).reference.has_value(); }
  float band() const { return band_; }

 private:
  // A mesh's reference field: its signed distance at one placement, resampled at each pose.
  struct Reference {
    engine::vk::Image field;     // R32F, the grid's layout; the band outside the mesh's box
    ImageHandle handle;          // its latest version in the graph being declared
    std::optional<float> scale;  // the mesh's scale the field holds (none: nothing yet)
    glm::mat4 placement{1.0f};   // the reference placement
  };
  struct Mesh {
    size_t obstacle = 0;          // index in the scene's obstacles
    engine::vk::Image triangles;  // RGBA32F, 3 texels per triangle (the mesh's frame)
    uint32_t triangle_count = 0;
    std::optional<Reference> reference;  // 3D only
  };
  // Where mesh `mesh` placed by `placement` would be voxelized into its reference field: the
  // placement moved by whole cells to the grid's centre, or none if its box does not fit.
  std::optional<glm::mat4> reference_placement(const TriangleMesh& mesh, const glm::mat4& placement) const;
  // The push constants of a voxelization of `mesh` at `placement` into slot `slot`, with `band`:
  // its box (the cells within the band of its bounds, clamped to the grid).
  gpu::MeshRasterPush raster_push(const TriangleMesh& mesh, const glm::mat4& placement, int slot, float band) const;
  // A reference's band: a cell past the field's, so that the resample's interpolation next to the
  // field's band reads distances, not the clamp, before it clamps them.
  float reference_band() const { return band_ + cell_size_; }
  // A pass drawn over a mesh's box: a spread pass, the field pass (into the field or a reference)
  // or the resample pass.
  struct BoxPass {
    const engine::vk::GraphicsPipeline* pipeline;  // the pass is named after it
    Access access;  // of its target: written, or MIN-blended (the field)
    engine::graph::AttachmentOptions target_options;  // loaded where blended, cleared for a reference
    std::vector<std::pair<uint32_t, ImageHandle>> inputs;  // binding, image (sampled)
    const engine::vk::Sampler* sampler;
  };
  static MeshBox box_of(const gpu::MeshRasterPush& push) { return {glm::ivec3(push.box_min), glm::ivec3(push.box_max)}; }
  // The triangles of meshes `meshes` (at `pushes`' placements) counted into `target`, cleared first.
  ImageHandle add_inside_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                              ImageHandle target, const std::vector<size_t>& meshes,
                              const std::vector<gpu::MeshRasterPush>& pushes, const std::vector<uint32_t>& instances) const;
  // Mesh `mesh`'s closest points within a cell of it into `nearest`, with `depth` (both cleared in its box).
  ImageHandle add_seed_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms, size_t mesh,
                            ImageHandle nearest, ImageHandle& depth, const gpu::MeshRasterPush& push,
                            uint32_t instances) const;
  // `pass` over `box` with push constants `push` into `target`; the boxes `reset` cleared to the
  // band first (the first pass into the field).
  ImageHandle add_box_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                           const BoxPass& pass, ImageHandle target, const MeshBox& box, std::span<const std::byte> push,
                           const std::vector<MeshBox>& reset = {}) const;
  // vkCmdClearAttachments of the pass's attachment 0 (or its depth) over `box`.
  void clear_box(VkCommandBuffer cmd, const MeshBox& box, VkClearValue value,
                 VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT) const;

  GridLayout layout_;
  float cell_size_ = 0.0f;
  float band_ = 0.0f;  // m
  std::vector<Mesh> meshes_;
  std::vector<ImageHandle> triangle_handles_;  // the last import()'s
  engine::vk::GraphicsPipeline inside_, seed_, spread_, field_pipeline_;
  std::optional<engine::vk::GraphicsPipeline> reference_pipeline_, resample_pipeline_;  // 3D
  engine::vk::Sampler nearest_, linear_;
  engine::vk::Image field_;
  engine::vk::Image inside_counts_;  // the inside pass's target: valid in the boxes it last counted
  ImageHandle inside_handle_;        // the last import()'s
  std::vector<MeshBox> written_;     // the boxes the field may hold distances in (else the band)
  std::vector<MeshBox> unconfirmed_;  // written_ before the last update(), until its graph runs
  std::optional<std::vector<glm::mat4>> voxelized_;  // the placements of the field's contents
  int voxelizations_ = 0;
  int triangle_voxelizations_ = 0;
};

}  // namespace liquid
