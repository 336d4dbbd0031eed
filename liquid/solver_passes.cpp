#include "liquid/solver_passes.h"

#include "engine/passes/fullscreen.h"

#include <cmath>

namespace liquid {

using engine::graph::Access;
using engine::graph::PassBuilder;
using engine::graph::PassContext;

ImageHandle add_splat(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                      const engine::vk::UniformSlice& uniforms, const ParticleImages& particles, ImageHandle splat,
                      int active_particles, float kernel_radius_cells) {
  struct Data {
    ImageHandle splat;
  };
  // In 3D each particle is drawn once per slice it may touch: the slice centres within r of it
  // are at most ceil(2 r) consecutive layers (splat.vert). Every instance costs vertex shading,
  // binning and point setup even when it is dropped, so no spare one is drawn.
  const uint32_t instances = pipelines.dimension == 3 ? uint32_t(std::ceil(2.0f * kernel_radius_cells)) : 1u;
  return graph
      .add_pass<Data>(
          "liquid.splat",
          [&](PassBuilder& b, Data& d) {
            b.read(particles.positions, Access::VertexSampled);
            b.read(particles.velocities, Access::VertexSampled);
            d.splat = b.write(splat, Access::ColorAttachmentBlend, engine::graph::clear_to(0, 0, 0, 0));
          },
          [&pipelines, uniforms, particles, active_particles, instances](PassContext& ctx, const Data&) {
            if (active_particles == 0) return;
            const auto& p = pipelines.splat;
            p.bind(ctx.cmd, ctx.width, ctx.height);
            p.push_uniform(ctx.cmd, 0, uniforms.buffer, uniforms.offset, uniforms.size);
            p.push_image(ctx.cmd, 1, ctx.image(particles.positions).sampled_view(), pipelines.nearest.handle());
            p.push_image(ctx.cmd, 2, ctx.image(particles.velocities).sampled_view(), pipelines.nearest.handle());
            vkCmdDraw(ctx.cmd, uint32_t(active_particles), instances, 0, 0);
          })
      .splat;
}

GridImages add_grid(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                    const engine::vk::UniformSlice& uniforms, ImageHandle splat, const GridImages& grids) {
  return graph.add_pass<GridImages>(
      "liquid.grid",
      [&](PassBuilder& b, GridImages& out) {
        b.read(splat, Access::FragmentSampled);
        out.velocity = b.write(grids.velocity, Access::ColorAttachmentWrite);
        out.density = b.write(grids.density, Access::ColorAttachmentWrite);
      },
      [&pipelines, uniforms, splat](PassContext& ctx, const GridImages&) {
        const auto& p = pipelines.grid;
        p.bind(ctx.cmd, ctx.width, ctx.height);
        p.push_uniform(ctx.cmd, 0, uniforms.buffer, uniforms.offset, uniforms.size);
        p.push_image(ctx.cmd, 1, ctx.image(splat).sampled_view(), pipelines.nearest.handle());
        engine::passes::draw_fullscreen(ctx.cmd, ctx.layers);
      });
}

ParticleImages add_particle_update(engine::graph::RenderGraph& graph, const SolverPipelines& pipelines,
                                   const engine::vk::UniformSlice& uniforms, const ParticleImages& current,
                                   ImageHandle splat, const GridImages& grids, const ParticleImages& next,
                                   int active_after) {
  return graph.add_pass<ParticleImages>(
      "liquid.particle",
      [&](PassBuilder& b, ParticleImages& out) {
        b.read(current.positions, Access::FragmentSampled);
        b.read(current.velocities, Access::FragmentSampled);
        b.read(splat, Access::FragmentSampled);
        b.read(grids.velocity, Access::FragmentSampled);
        out.positions = b.write(next.positions, Access::ColorAttachmentWrite);
        out.velocities = b.write(next.velocities, Access::ColorAttachmentWrite);
      },
      [&pipelines, uniforms, current, splat, grids, active_after](PassContext& ctx, const ParticleImages&) {
        if (active_after == 0) return;
        const auto& p = pipelines.particle;
        p.bind(ctx.cmd, ctx.width, ctx.height);
        // Only the rows that hold active (or newly emitted) particles are shaded.
        const uint32_t rows = (uint32_t(active_after) + ctx.width - 1) / ctx.width;
        const VkRect2D scissor{{0, 0}, {ctx.width, rows}};
        vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
        p.push_uniform(ctx.cmd, 0, uniforms.buffer, uniforms.offset, uniforms.size);
        const VkSampler s = pipelines.nearest.handle();
        p.push_image(ctx.cmd, 1, ctx.image(current.positions).sampled_view(), s);
        p.push_image(ctx.cmd, 2, ctx.image(current.velocities).sampled_view(), s);
        p.push_image(ctx.cmd, 3, ctx.image(splat).sampled_view(), s);
        p.push_image(ctx.cmd, 4, ctx.image(grids.velocity).sampled_view(), s);
        engine::passes::draw_fullscreen(ctx.cmd);
      });
}

}  // namespace liquid
