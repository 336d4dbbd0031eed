#include "liquid/solver/mesh_field.h"

#include "engine/graph/transfer.h"
#include "engine/passes/bindings.h"
#include "engine/passes/fullscreen.h"
#include "liquid/physics/mesh.h"
#include "liquid/solver/uniforms.h"
#include "liquid_shaders.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace liquid {

namespace {

constexpr uint32_t k_triangle_texture_width = LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH;
constexpr VkImageUsageFlags k_field_usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

// The raster passes' vertex shader by the grid's layout (how a primitive reaches its slice).
std::span<const uint32_t> raster_vertex(const GridLayout& layout, bool band) {
  using namespace liquid_shaders;
  if (layout.dimension == 2) return band ? mesh_band_vert_2d : mesh_inside_vert_2d;
  if (layout.atlas()) return band ? mesh_band_vert_3d_atlas : mesh_inside_vert_3d_atlas;
  if (layout.path == GridPath::GeometryShader) return band ? mesh_band_vert_3d_gs : mesh_inside_vert_3d_gs;
  return band ? mesh_band_vert_3d : mesh_inside_vert_3d;
}

engine::vk::GraphicsPipelineDesc raster_pipeline(const GridLayout& layout, bool band,
                                                 const std::vector<int32_t>& specialization) {
  using namespace liquid_shaders;
  const bool geometry = layout.layered() && layout.path == GridPath::GeometryShader;
  return engine::vk::GraphicsPipelineDesc{
      .name = band ? "liquid.mesh_band" : "liquid.mesh_inside",
      .vertex = raster_vertex(layout, band),
      .geometry = geometry ? std::span<const uint32_t>(band ? mesh_band_geom : mesh_inside_geom)
                           : std::span<const uint32_t>{},
      .fragment = band ? layout.pick(mesh_band_frag_2d, mesh_band_frag_3d, mesh_band_frag_3d_atlas)
                       : layout.pick(mesh_inside_frag_2d, mesh_inside_frag_3d, mesh_inside_frag_3d_atlas),
      .color_formats = {k_mesh_field_format},
      .blend = {band ? engine::vk::BlendMode::Min : engine::vk::BlendMode::Additive},
      .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                   {LIQUID_BINDING_MESH_TRIANGLES, DescriptorKind::SampledImage, VK_SHADER_STAGE_VERTEX_BIT}},
      .push_constant_size = sizeof(gpu::MeshRasterPush),
      .specialization = specialization};
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
                     [](const Obstacle& o) { return o.shape == ObstacleShape::Mesh; });
}

void add_mesh_field_binding(bool meshes, std::vector<engine::vk::DescriptorBinding>& bindings) {
  if (meshes) bindings.push_back({LIQUID_BINDING_MESH_FIELD, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT});
}

void bind_mesh_field(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle field,
                     const engine::vk::Sampler& linear) {
  if (field.valid()) bindings.bind_image(builder, LIQUID_BINDING_MESH_FIELD, field, linear.handle());
}

MeshField::MeshField(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup,
                     const GridLayout& layout, const std::vector<int32_t>& specialization)
    : layout_(layout), cell_size_(setup.cell_size),
      band_(setup.obstacle_band + gpu::k_mesh_field_margin_cells * setup.cell_size),
      inside_(context, raster_pipeline(layout, false, specialization)),
      band_pipeline_(context, raster_pipeline(layout, true, specialization)),
      field_pipeline_(context,
                      engine::vk::GraphicsPipelineDesc{
                          .name = "liquid.mesh_field",
                          .vertex = grid_pass_shaders(layout).vertex,
                          .geometry = grid_pass_shaders(layout).geometry,
                          .fragment = layout.pick(liquid_shaders::mesh_field_frag_2d, liquid_shaders::mesh_field_frag_3d,
                                                  liquid_shaders::mesh_field_frag_3d_atlas),
                          .color_formats = {k_mesh_field_format},
                          .bindings = {{LIQUID_BINDING_SOLVER_UNIFORMS, DescriptorKind::UniformBuffer, k_solver_uniform_stages},
                                       {LIQUID_BINDING_MESH_INSIDE, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT},
                                       {LIQUID_BINDING_MESH_BAND, DescriptorKind::SampledImage, VK_SHADER_STAGE_FRAGMENT_BIT}},
                          .push_constant_size = sizeof(gpu::MeshRasterPush),
                          .specialization = specialization}),
      nearest_(context, VK_FILTER_NEAREST),
      field_(context, layout.image_desc(k_mesh_field_format, k_field_usage), "liquid.mesh_field") {
  // Far from every mesh until the first voxelization, so a view drawn before the first step reads
  // defined contents.
  const std::vector<glm::vec4> far(layout.image_desc(k_mesh_field_format, 0).width *
                                       size_t(layout.image_desc(k_mesh_field_format, 0).height) *
                                       layout.image_desc(k_mesh_field_format, 0).depth_or_layers,
                                   glm::vec4(band_));
  engine::graph::upload_image(context, field_, std::as_bytes(std::span(far)));
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Obstacle& o = scene.obstacles[i];
    if (o.shape != ObstacleShape::Mesh) continue;
    meshes_.push_back({i, mesh_triangle_texture(context, o.mesh, "liquid.mesh_triangles" + std::to_string(meshes_.size())),
                       uint32_t(o.mesh.indices.size() / 3)});
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
  for (Mesh& m : meshes_) triangle_handles_.push_back(graph.import_image(m.triangles.name(), m.triangles));
  return graph.import_image(field_.name(), field_);
}

ImageHandle MeshField::update(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                              const std::vector<Obstacle>& obstacles, const std::vector<ObstaclePose>& poses,
                              ImageHandle field) {
  std::vector<glm::mat4> placements;
  for (const Mesh& m : meshes_) placements.push_back(mesh_to_world(obstacles[m.obstacle].mesh, poses[m.obstacle].center));
  if (voxelized_ == placements) return field;
  voxelized_ = placements;
  ++voxelizations_;

  // Per mesh: the push constants, the inside pass's slices (centres within the mesh's z range) and
  // the band pass's instances (the most slices one triangle's band reaches).
  std::vector<gpu::MeshRasterPush> pushes;
  std::vector<uint32_t> slices;     // the inside pass's instances
  std::vector<uint32_t> instances;  // the band pass's
  for (size_t k = 0; k < meshes_.size(); ++k) {
    const TriangleMesh& mesh = obstacles[meshes_[k].obstacle].mesh;
    gpu::MeshRasterPush push{};
    push.local_to_world = placements[k];
    push.slot = int(k);
    push.band = band_;
    float lo = INFINITY, hi = -INFINITY;
    for (const glm::vec3& v : mesh.vertices) {
      const float z = (placements[k] * glm::vec4(v, 1.0f)).z / cell_size_;
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    const int first = std::max(int(std::ceil(lo - 0.5f)), 0);
    const int last = std::min(int(std::floor(hi - 0.5f)), layout_.cells.z - 1);
    push.first_slice = first;
    pushes.push_back(push);
    slices.push_back(layout_.dimension == 3 ? uint32_t(std::max(last - first + 1, 0)) : 1u);
    const float reach = longest_edge(mesh) * mesh.scale / cell_size_ + 2.0f * band_ / cell_size_;
    instances.push_back(layout_.dimension == 3 ? uint32_t(std::ceil(reach)) + 1 : 1u);
  }

  const engine::vk::ImageDesc desc = layout_.image_desc(k_mesh_field_format, 0);
  // The inside pass draws each triangle; the band pass a rectangle (two triangles) per triangle.
  const ImageHandle inside = add_raster_pass(graph, uniforms, {"liquid.mesh_inside", &inside_, 3, 0.0f},
                                             graph.create_image("liquid.mesh_inside", desc), pushes, slices);
  const ImageHandle band = add_raster_pass(graph, uniforms, {"liquid.mesh_band", &band_pipeline_, 6, LIQUID_MESH_FAR},
                                           graph.create_image("liquid.mesh_band", desc), pushes, instances);

  struct Data {
    engine::passes::PassBindings bindings;
    ImageHandle field;
  };
  gpu::MeshRasterPush push{};
  push.band = band_;
  return graph
      .add_pass<Data>(
          "liquid.mesh_field",
          [&](PassBuilder& b, Data& d) {
            d.bindings = engine::passes::PassBindings(field_pipeline_);
            d.bindings.bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
            d.bindings.bind_image(b, LIQUID_BINDING_MESH_INSIDE, inside, nearest_.handle());
            d.bindings.bind_image(b, LIQUID_BINDING_MESH_BAND, band, nearest_.handle());
            d.field = b.write(field, Access::ColorAttachmentWrite);
          },
          [this, push](PassContext& ctx, const Data& d) {
            d.bindings.bind_and_push(ctx);
            field_pipeline_.push_constants(ctx.cmd, push);
            engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
          })
      .field;
}

ImageHandle MeshField::add_raster_pass(engine::graph::RenderGraph& graph, const engine::vk::UniformSlice& uniforms,
                                       const RasterPass& pass, ImageHandle target,
                                       const std::vector<gpu::MeshRasterPush>& pushes,
                                       const std::vector<uint32_t>& instances) const {
  struct Data {
    std::vector<engine::passes::PassBindings> bindings;  // one per mesh (its triangles)
    ImageHandle target;
  };
  return graph
      .add_pass<Data>(
          pass.name,
          [&](PassBuilder& b, Data& d) {
            for (ImageHandle triangles : triangle_handles_) {
              d.bindings.emplace_back(*pass.pipeline);
              d.bindings.back().bind_uniform(LIQUID_BINDING_SOLVER_UNIFORMS, uniforms);
              d.bindings.back().bind_image(b, LIQUID_BINDING_MESH_TRIANGLES, triangles, nearest_.handle());
            }
            const float c = pass.clear;
            d.target = b.write(target, Access::ColorAttachmentBlend, engine::graph::clear_to(c, c, c, c));
          },
          [this, pass, pushes, instances](PassContext& ctx, const Data& d) {
            for (size_t k = 0; k < meshes_.size(); ++k) {
              if (instances[k] == 0) continue;
              d.bindings[k].bind_and_push(ctx);
              pass.pipeline->push_constants(ctx.cmd, pushes[k]);
              vkCmdDraw(ctx.cmd, pass.vertices_per_triangle * meshes_[k].triangle_count, instances[k], 0, 0);
            }
          })
      .target;
}

}  // namespace liquid
