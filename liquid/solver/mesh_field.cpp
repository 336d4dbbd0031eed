#include "liquid/solver/mesh_field.h"

#include "engine/graph/transfer.h"
#include "engine/passes/bindings.h"
#include "liquid/physics/mesh.h"
#include "liquid/solver/solver_pass.h"
#include "liquid_shader_families.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace liquid {

namespace {

constexpr uint32_t k_triangle_texture_width = LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH;
constexpr VkImageUsageFlags k_field_usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
// The closest surface points (xyz, m) of the seed and spread passes.
constexpr VkFormat k_nearest_format = VK_FORMAT_R32G32B32A32_SFLOAT;
// A mesh's reference field: its signed distance alone.
constexpr VkFormat k_reference_format = VK_FORMAT_R32_SFLOAT;
// The inside pass's crossing counts: small whole numbers, exact in half floats.
constexpr VkFormat k_inside_format = VK_FORMAT_R16G16B16A16_SFLOAT;
// The seed pass's depth: a cell's distance to the closest triangle so far, over the band.
constexpr VkFormat k_seed_depth_format = VK_FORMAT_D32_SFLOAT;

engine::vk::GraphicsPipelineDesc raster_pipeline(const GridLayout& layout, bool seed,
                                                 const std::vector<int32_t>& specialization) {
  // The vertex shader by the grid's layout (how a primitive reaches its slice).
  const bool geometry = layout.layered() && layout.path == GridPath::GeometryShader;
  return engine::vk::GraphicsPipelineDesc{
      .name = seed ? "liquid.mesh_seed" : "liquid.mesh_inside",
      .vertex = shader_variant(seed ? shaders::mesh_seed_vert : shaders::mesh_inside_vert, layout),
      .geometry = geometry ? shader_variant(seed ? shaders::mesh_seed_geom : shaders::mesh_inside_geom)
                           : std::span<const uint32_t>{},
      .fragment = shader_variant(seed ? shaders::mesh_seed_frag : shaders::mesh_inside_frag, layout),
      .color_formats = {seed ? k_nearest_format : k_inside_format},
      .blend = {seed ? engine::vk::BlendMode::None : engine::vk::BlendMode::Additive},
      .depth_format = seed ? k_seed_depth_format : VK_FORMAT_UNDEFINED,
      .depth_test = seed,
      .depth_write = seed,
      .depth_compare = VK_COMPARE_OP_LESS,
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {LIQUID_BINDING_MESH_TRIANGLES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .push_constant_size = sizeof(gpu::MeshRasterPush),
      .specialization = specialization};
}

// The passes drawn over a mesh's box.
enum class BoxKind {
  Spread,     // a jump-flood step: closest points to closest points
  Field,      // the last step and the signed distance, into the mesh's channel of the field
  Reference,  // the same into the mesh's own reference field (3D)
  Resample,   // the reference at a pose, into the mesh's channel of the field (3D)
};

engine::vk::GraphicsPipelineDesc box_pipeline(const GridLayout& layout, BoxKind kind,
                                              const std::vector<int32_t>& specialization) {
  engine::vk::GraphicsPipelineDesc desc{
      .vertex = grid_pass_shaders(layout).vertex,
      .geometry = grid_pass_shaders(layout).geometry,
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages}},
      .push_constant_size = sizeof(gpu::MeshRasterPush),
      .specialization = specialization};
  const auto sampled = [&desc](uint32_t binding) {
    desc.bindings.push_back({binding, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
  };
  switch (kind) {
    case BoxKind::Spread:
      desc.name = "liquid.mesh_spread";
      desc.fragment = shader_variant(shaders::mesh_spread_frag, layout);
      desc.color_formats = {k_nearest_format};
      sampled(LIQUID_BINDING_MESH_NEAREST);
      break;
    case BoxKind::Field:
      desc.name = "liquid.mesh_field";
      desc.fragment = shader_variant(shaders::mesh_field_frag, layout);
      desc.color_formats = {k_mesh_field_format};
      desc.blend = {engine::vk::BlendMode::Min};
      sampled(LIQUID_BINDING_MESH_NEAREST);
      sampled(LIQUID_BINDING_MESH_INSIDE);
      break;
    case BoxKind::Reference:
      desc.name = "liquid.mesh_reference";
      desc.fragment = shader_variant(shaders::mesh_reference_frag, layout);
      desc.color_formats = {k_reference_format};
      sampled(LIQUID_BINDING_MESH_NEAREST);
      sampled(LIQUID_BINDING_MESH_INSIDE);
      break;
    case BoxKind::Resample:
      desc.name = "liquid.mesh_resample";
      desc.fragment = shader_variant(shaders::mesh_resample_frag, layout);
      desc.color_formats = {k_mesh_field_format};
      desc.blend = {engine::vk::BlendMode::Min};
      desc.push_constant_size = sizeof(gpu::MeshResamplePush);
      sampled(LIQUID_BINDING_MESH_REFERENCE);
      break;
  }
  return desc;
}

// The bounds (in cells) of `mesh` placed by `placement`.
std::pair<glm::vec3, glm::vec3> bounds_in_cells(const TriangleMesh& mesh, const glm::mat4& placement, float cell_size) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : mesh.vertices) {
    const glm::vec3 p = glm::vec3(placement * glm::vec4(v, 1.0f)) / cell_size;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {lo, hi};
}

// The largest z extent (m) of a triangle of `mesh` placed by `placement`.
float tallest_triangle(const TriangleMesh& mesh, const glm::mat4& placement) {
  float tallest = 0.0f;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    float lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < 3; ++k) {
      const float z = (placement * glm::vec4(mesh.vertices[mesh.indices[i + k]], 1.0f)).z;
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    tallest = std::max(tallest, hi - lo);
  }
  return tallest;
}

// The image description of a grid-shaped depth attachment: layers where the grid is a 3D image
// (a depth image cannot be 3D).
engine::vk::ImageDesc depth_desc(const GridLayout& layout) {
  engine::vk::ImageDesc desc = layout.image_desc(k_seed_depth_format, 0);
  if (desc.kind == engine::vk::ImageKind::Image3D) desc.kind = engine::vk::ImageKind::Image2DArray;
  return desc;
}

// The jump flood's steps, halving down to 1, for a band of `band_cells`: with the field pass's 1
// they reach 2 * first cells along each axis, which must be as far as a seed within
// LIQUID_MESH_SEED_CELLS of the surface is from a cell at the band's edge, plus half a cell for the
// seed's offset from the cell's foot.
std::vector<int> jump_flood_steps(float band_cells) {
  const int reach = int(std::ceil(band_cells - gpu::k_mesh_seed_cells + 0.5f));
  std::vector<int> steps{1};
  while (2 * steps.front() < reach) steps.insert(steps.begin(), 2 * steps.front());
  return steps;
}

}  // namespace

engine::vk::Image mesh_triangle_texture(engine::vk::Context& context, const TriangleMesh& mesh, const std::string& name) {
  const size_t texels = mesh.indices.size();
  const uint32_t rows = uint32_t((texels + k_triangle_texture_width - 1) / k_triangle_texture_width);
  engine::vk::Image image(context,
                          {engine::vk::ImageKind::Image2D, k_triangle_texture_width, rows, 1, VK_FORMAT_R32G32B32A32_SFLOAT,
                           VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                          name);
  std::vector<glm::vec4> data(size_t(rows) * k_triangle_texture_width, glm::vec4(0.0f));
  for (size_t i = 0; i < texels; ++i) data[i] = glm::vec4(mesh.vertices[mesh.indices[i]], 1.0f);
  engine::graph::upload_image(context, image, std::as_bytes(std::span(data)));
  return image;
}

bool has_mesh_obstacles(const Scene& scene) {
  return std::any_of(scene.obstacles.begin(), scene.obstacles.end(),
                     [](const Obstacle& o) { return o.shape == ObstacleShape::Mesh && !o.dynamic; });
}

void add_mesh_field_binding(bool meshes, std::vector<engine::vk::DescriptorBinding>& bindings) {
  if (meshes) bindings.push_back({LIQUID_BINDING_MESH_FIELD, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
}

void bind_mesh_field(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle field,
                     const engine::vk::Sampler& linear) {
  if (field.valid()) bindings.bind_image(builder, LIQUID_BINDING_MESH_FIELD, field, linear.handle());
}

std::vector<VkClearRect> mesh_box_rects(const GridLayout& layout, const MeshBox& box) {
  const glm::ivec3 size = box.max - box.min;
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) return {};
  if (!layout.atlas())
    return {{{{box.min.x, box.min.y}, {uint32_t(size.x), uint32_t(size.y)}}, uint32_t(box.min.z), uint32_t(size.z)}};
  std::vector<VkClearRect> rects;
  for (int z = box.min.z; z < box.max.z; ++z) {
    const glm::ivec2 tile = glm::ivec2(z % layout.tiles.x, z / layout.tiles.x) * glm::ivec2(layout.cells);
    rects.push_back({{{tile.x + box.min.x, tile.y + box.min.y}, {uint32_t(size.x), uint32_t(size.y)}}, 0, 1});
  }
  return rects;
}

MeshField::MeshField(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup,
                     const GridLayout& layout, const std::vector<int32_t>& specialization)
    : layout_(layout), cell_size_(setup.cell_size),
      band_(setup.obstacle_band + gpu::k_mesh_field_margin_cells * setup.cell_size),
      inside_(context, raster_pipeline(layout, false, specialization)),
      seed_(context, raster_pipeline(layout, true, specialization)),
      spread_(context, box_pipeline(layout, BoxKind::Spread, specialization)),
      field_pipeline_(context, box_pipeline(layout, BoxKind::Field, specialization)),
      nearest_(context, VK_FILTER_NEAREST),
      linear_(context, VK_FILTER_LINEAR),
      field_(context, layout.image_desc(k_mesh_field_format, k_field_usage), "liquid.mesh_field"),
      inside_counts_(context,
                     layout.image_desc(k_inside_format, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT),
                     "liquid.mesh_inside") {
  // Far from every mesh until the first voxelization, so a view drawn before the first step reads
  // defined contents.
  const engine::vk::ImageDesc desc = layout.image_desc(k_mesh_field_format, 0);
  const std::vector<glm::vec4> far(size_t(desc.width) * desc.height * desc.depth_or_layers, glm::vec4(band_));
  engine::graph::upload_image(context, field_, std::as_bytes(std::span(far)));
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    if (o.shape != ObstacleShape::Mesh || o.dynamic) continue;  // a dynamic mesh carries its own distance (body_shapes.h)
    const std::string index = std::to_string(meshes_.size());
    meshes_.push_back({i, mesh_triangle_texture(context, o.mesh, "liquid.mesh_triangles" + index),
                       uint32_t(o.mesh.indices.size() / 3), std::nullopt});
    // A reference field where the mesh fits in the grid at its first scale.
    if (layout.dimension == 3 && reference_placement(o.mesh, mesh_to_world(o.mesh, o.center)))
      meshes_.back().reference = Reference{
          engine::vk::Image(context,
                            layout.image_desc(k_reference_format,
                                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT),
                            "liquid.mesh_reference" + index),
          {}, std::nullopt, glm::mat4(1.0f)};
  }
  if (std::any_of(meshes_.begin(), meshes_.end(), [](const Mesh& m) { return m.reference.has_value(); })) {
    reference_pipeline_.emplace(context, box_pipeline(layout, BoxKind::Reference, specialization));
    resample_pipeline_.emplace(context, box_pipeline(layout, BoxKind::Resample, specialization));
  }
}

std::vector<glm::vec4> MeshField::read(engine::vk::Context& context) {
  const std::vector<std::byte> bytes = engine::graph::download_image(context, field_);
  std::vector<glm::vec4> texels(bytes.size() / sizeof(glm::vec4));
  std::memcpy(texels.data(), bytes.data(), texels.size() * sizeof(glm::vec4));
  return layout_.to_linear(texels);
}

ImageHandle MeshField::import(engine::graph::RenderGraph& graph) {
  triangle_handles_.clear();
  for (Mesh& m : meshes_) {
    triangle_handles_.push_back(graph.import_image(m.triangles.name(), m.triangles));
    if (m.reference) m.reference->handle = graph.import_image(m.reference->field.name(), m.reference->field);
  }
  inside_handle_ = graph.import_image(inside_counts_.name(), inside_counts_);
  return graph.import_image(field_.name(), field_);
}

void MeshField::invalidate() {
  voxelized_.reset();
  written_.insert(written_.end(), unconfirmed_.begin(), unconfirmed_.end());
  for (Mesh& m : meshes_)
    if (m.reference) m.reference->scale.reset();  // its voxelization may not have run either
}

std::optional<glm::mat4> MeshField::reference_placement(const TriangleMesh& mesh, const glm::mat4& placement) const {
  const auto [lo, hi] = bounds_in_cells(mesh, placement, cell_size_);
  // Whole cells, so that where the pose is the reference's moved by whole cells the resample reads
  // the reference's texels exactly.
  const glm::vec3 shift = glm::round(glm::vec3(layout_.cells) * 0.5f - 0.5f * (lo + hi));
  // The box of the reference's band and one cell more: the reference's edge cells hold its band,
  // which the resample's clamp to the grid's edge then reads past it.
  const float reach = reference_band() / cell_size_ + 1.0f;
  if (glm::any(glm::lessThan(lo + shift - reach, glm::vec3(0.0f))) ||
      glm::any(glm::greaterThan(hi + shift + reach, glm::vec3(layout_.cells))))
    return std::nullopt;
  return glm::translate(glm::mat4(1.0f), shift * cell_size_) * placement;
}

gpu::MeshRasterPush MeshField::raster_push(const TriangleMesh& mesh, const glm::mat4& placement, int slot,
                                           float band) const {
  const float band_cells = band / cell_size_;
  const auto [lo, hi] = bounds_in_cells(mesh, placement, cell_size_);
  gpu::MeshRasterPush push{};
  push.local_to_world = placement;
  push.slot = slot;
  push.band = band;
  const glm::ivec3 cells = layout_.cells;
  push.box_min = glm::ivec4(glm::clamp(glm::ivec3(glm::floor(lo - band_cells)), glm::ivec3(0), cells), 0);
  push.box_max = glm::ivec4(glm::clamp(glm::ivec3(glm::ceil(hi + band_cells)), glm::ivec3(0), cells), 0);
  if (layout_.dimension == 2) {  // the cells at z = 0: the mesh's cross-section, if it has one there
    const bool crosses = lo.z - band_cells < 0.0f && hi.z + band_cells > 0.0f;
    push.box_min.z = 0;
    push.box_max.z = crosses ? 1 : 0;
  }
  return push;
}

ImageHandle MeshField::update(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                              const std::vector<Obstacle>& obstacles, const std::vector<ObstaclePose>& poses,
                              ImageHandle field) {
  std::vector<glm::mat4> placements;
  for (const Mesh& m : meshes_) placements.push_back(mesh_to_world(obstacles[m.obstacle].mesh, poses[m.obstacle].center));
  if (voxelized_ == placements) return field;
  voxelized_ = placements;
  ++voxelizations_;

  // Per mesh, how this field is made: from its triangles (into its reference, when it has none of
  // its scale yet, or into the field at the pose when it has no reference), and from its reference.
  struct Voxelization {
    size_t mesh;
    gpu::MeshRasterPush push;  // at the placement voxelized
    bool into_reference;
    uint32_t inside_instances = 1, seed_instances = 1;
  };
  std::vector<gpu::MeshRasterPush> at_pose;  // each mesh's at its placement: its box in the field
  for (size_t k = 0; k < meshes_.size(); ++k)
    at_pose.push_back(raster_push(obstacles[meshes_[k].obstacle].mesh, placements[k], int(k), band_));
  std::vector<Voxelization> voxelizations;
  std::vector<bool> resampled(meshes_.size(), false);
  for (size_t k = 0; k < meshes_.size(); ++k) {
    const TriangleMesh& mesh = obstacles[meshes_[k].obstacle].mesh;
    std::optional<Reference>& reference = meshes_[k].reference;
    std::optional<glm::mat4> at;
    if (reference && reference->scale != mesh.scale) {
      at = reference_placement(mesh, placements[k]);
      reference->scale.reset();
      if (at) {
        reference->scale = mesh.scale;
        reference->placement = *at;
      }
    }
    resampled[k] = reference && reference->scale;
    if (resampled[k] && !at) continue;  // its reference holds it
    const glm::mat4 placement = at ? *at : placements[k];
    Voxelization v{k, at ? raster_push(mesh, *at, int(k), reference_band()) : at_pose[k], at.has_value()};
    // The tallest triangle (cells): the inside pass's slices per triangle are at most its
    // height rounded up, plus one; the seed pass's the whole number of slice centres within its
    // height plus the seed band on either side (a thousandth for the GPU's rounding).
    if (layout_.dimension == 3) {
      const float tallest = tallest_triangle(mesh, placement) / cell_size_;
      v.inside_instances = uint32_t(std::ceil(tallest)) + 1;
      v.seed_instances = uint32_t(std::floor(tallest + 2.0f * gpu::k_mesh_seed_cells + 1e-3f)) + 1;
    }
    voxelizations.push_back(v);
  }
  if (!voxelizations.empty()) ++triangle_voxelizations_;

  // The boxes at the poses. The field holds distances only in the boxes of the last update (or of
  // the ones before, if its graph did not run): those are reset to the band by the first pass into it.
  std::vector<MeshBox> boxes;
  for (const gpu::MeshRasterPush& push : at_pose) boxes.push_back(box_of(push));
  std::vector<MeshBox> reset = written_;
  reset.insert(reset.end(), boxes.begin(), boxes.end());
  unconfirmed_ = std::exchange(written_, boxes);
  const auto reset_once = [&reset]() { return std::exchange(reset, {}); };

  const engine::vk::ImageDesc nearest_desc = layout_.image_desc(k_nearest_format, 0);
  ImageHandle inside;
  if (!voxelizations.empty()) {
    std::vector<size_t> meshes;
    std::vector<gpu::MeshRasterPush> pushes;
    std::vector<uint32_t> instances;
    for (const Voxelization& v : voxelizations) {
      meshes.push_back(v.mesh);
      pushes.push_back(v.push);
      instances.push_back(v.inside_instances);
    }
    inside = add_inside_pass(graph, uniforms, graph.latest(inside_handle_), meshes, pushes, instances);
  }
  ImageHandle nearest = graph.create_image("liquid.mesh_nearest", nearest_desc);
  ImageHandle spread = graph.create_image("liquid.mesh_spread", nearest_desc);
  ImageHandle depth = graph.create_image("liquid.mesh_seed_depth", depth_desc(layout_));
  for (Voxelization& v : voxelizations) {
    nearest = add_seed_pass(graph, uniforms, v.mesh, nearest, depth, v.push, v.seed_instances);
    for (int step : jump_flood_steps(v.push.band / cell_size_)) {
      v.push.step = step;
      spread = add_box_pass(graph, uniforms, {&spread_, Access::ColorAttachmentWrite, {},
                                              {{LIQUID_BINDING_MESH_NEAREST, nearest}}, &nearest_},
                            spread, box_of(v.push), std::as_bytes(std::span(&v.push, 1)));
      std::swap(nearest, spread);
    }
    v.push.step = 1;
    const std::vector<std::pair<uint32_t, ImageHandle>> inputs{{LIQUID_BINDING_MESH_NEAREST, nearest},
                                                               {LIQUID_BINDING_MESH_INSIDE, inside}};
    if (v.into_reference) {
      // The whole reference cleared to the band (it is redone only when the mesh's scale changes).
      Reference& reference = *meshes_[v.mesh].reference;
      const BoxPass pass{&*reference_pipeline_, Access::ColorAttachmentWrite,
                         engine::graph::clear_to(reference_band(), 0.0f, 0.0f, 0.0f), inputs, &nearest_};
      reference.handle = add_box_pass(graph, uniforms, pass, graph.latest(reference.handle), box_of(v.push),
                                      std::as_bytes(std::span(&v.push, 1)));
    } else {
      const BoxPass pass{&field_pipeline_, Access::ColorAttachmentBlend,
                         {engine::graph::LoadOp::Load, {}}, inputs, &nearest_};
      field = add_box_pass(graph, uniforms, pass, field, box_of(v.push), std::as_bytes(std::span(&v.push, 1)),
                           reset_once());
    }
  }
  for (size_t k = 0; k < meshes_.size(); ++k) {
    if (!resampled[k]) continue;
    Reference& reference = *meshes_[k].reference;
    gpu::MeshResamplePush push{};
    // In double precision, so that a pose moved by whole cells from the reference maps cell
    // centres onto cell centres.
    push.reference_from_world = glm::mat4(glm::dmat4(reference.placement) * glm::inverse(glm::dmat4(placements[k])));
    push.slot = int(k);
    push.band = band_;
    const BoxPass pass{&*resample_pipeline_, Access::ColorAttachmentBlend,
                       {engine::graph::LoadOp::Load, {}}, {{LIQUID_BINDING_MESH_REFERENCE, graph.latest(reference.handle)}},
                       &linear_};
    field = add_box_pass(graph, uniforms, pass, field, boxes[k], std::as_bytes(std::span(&push, 1)), reset_once());
  }
  return field;
}

ImageHandle MeshField::add_inside_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                       ImageHandle target, const std::vector<size_t>& meshes,
                                       const std::vector<gpu::MeshRasterPush>& pushes,
                                       const std::vector<uint32_t>& instances) const {
  struct Data {
    std::vector<engine::passes::PassBindings> bindings;  // one per mesh counted (its triangles)
    ImageHandle target;
  };
  return graph
      .add_pass<Data>(
          "liquid.mesh_inside",
          [&](PassBuilder& b, Data& d) {
            for (size_t mesh : meshes) {
              d.bindings.emplace_back(inside_);
              d.bindings.back().bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
              d.bindings.back().bind_image(b, LIQUID_BINDING_MESH_TRIANGLES, triangle_handles_[mesh], nearest_.handle());
            }
            d.target = b.write(target, Access::ColorAttachmentBlend, {engine::graph::LoadOp::Load, {}});
          },
          [this, meshes, pushes, instances](PassContext& ctx, const Data& d) {
            // Only the meshes' boxes are counted in and read: zeroed, all before any mesh adds.
            for (const gpu::MeshRasterPush& push : pushes) clear_box(ctx.cmd, box_of(push), VkClearValue{});
            for (size_t i = 0; i < meshes.size(); ++i) {
              d.bindings[i].bind_and_push(ctx);
              inside_.push_constants(ctx.cmd, pushes[i]);
              vkCmdDraw(ctx.cmd, 3 * meshes_[meshes[i]].triangle_count, instances[i], 0, 0);
            }
          })
      .target;
}

ImageHandle MeshField::add_seed_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                     size_t mesh, ImageHandle nearest, ImageHandle& depth,
                                     const gpu::MeshRasterPush& push, uint32_t instances) const {
  return add_solver_pass<ImageHandle>(
      graph, seed_, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        bindings.bind_image(b, LIQUID_BINDING_MESH_TRIANGLES, triangle_handles_[mesh], nearest_.handle());
        const ImageHandle out = b.write(nearest, Access::ColorAttachmentWrite);
        depth = b.write(depth, Access::DepthAttachmentWrite);
        return out;
      },
      [this, mesh, push, instances](const PassContext& ctx) {
        // The box starts with no closest point, at the greatest depth.
        VkClearValue far{};
        far.color = {{LIQUID_MESH_FAR, LIQUID_MESH_FAR, LIQUID_MESH_FAR, 0.0f}};
        clear_box(ctx.cmd, box_of(push), far);
        VkClearValue deepest{};
        deepest.depthStencil = {1.0f, 0};
        clear_box(ctx.cmd, box_of(push), deepest, VK_IMAGE_ASPECT_DEPTH_BIT);
        seed_.push_constants(ctx.cmd, push);
        // A triangle holding the cells within the seed band, per triangle and slice.
        vkCmdDraw(ctx.cmd, 3 * meshes_[mesh].triangle_count, instances, 0, 0);
      });
}

ImageHandle MeshField::add_box_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                    const BoxPass& pass, ImageHandle target, const MeshBox& box,
                                    std::span<const std::byte> push, const std::vector<MeshBox>& reset) const {
  return add_solver_pass<ImageHandle>(
      graph, *pass.pipeline, uniforms,
      [&](engine::passes::PassBindings& bindings, PassBuilder& b) {
        for (const auto& [binding, image] : pass.inputs) bindings.bind_image(b, binding, image, pass.sampler->handle());
        return b.write(target, pass.access, pass.target_options);
      },
      [this, pipeline = pass.pipeline, box, push = std::vector<std::byte>(push.begin(), push.end()),
       reset](const PassContext& ctx) {
        VkClearValue band{};
        band.color = {{band_, band_, band_, band_}};
        for (const MeshBox& b : reset) clear_box(ctx.cmd, b, band);
        pipeline->push_constants(ctx.cmd, push.data(), uint32_t(push.size()));
        // The full-screen triangle, cut to the box by the scissor: once per slice of it on the
        // layered paths (the instance is the slice), once per tile in the atlas.
        for (const VkClearRect& rect : mesh_box_rects(layout_, box)) {
          vkCmdSetScissor(ctx.cmd, 0, 1, &rect.rect);
          vkCmdDraw(ctx.cmd, 3, rect.layerCount, 0, rect.baseArrayLayer);
        }
      });
}

void MeshField::clear_box(VkCommandBuffer cmd, const MeshBox& box, VkClearValue value, VkImageAspectFlags aspect) const {
  const std::vector<VkClearRect> rects = mesh_box_rects(layout_, box);
  if (rects.empty()) return;
  const VkClearAttachment attachment{aspect, 0, value};
  vkCmdClearAttachments(cmd, 1, &attachment, uint32_t(rects.size()), rects.data());
}

}  // namespace liquid
