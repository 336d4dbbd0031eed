// Running one configuration: the node and renderer a host engine would hold, driven through the
// tools' frame loop, with each frame's pass timings split into solver and rendering.
#include "tools/liquid_benchmark/run.h"

#include "tools/common/frame_loop.h"

#include "engine/vk/image.h"

#include "liquid/camera.h"
#include "liquid/node.h"
#include "liquid/renderer.h"
#include "liquid/solver/simulation.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>

namespace tools::benchmark {

Stats stats_of(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

Figures figures_of(const Result& r, int steps_per_frame) {
  Figures f;
  f.frame = stats_of(r.frame_ms);
  // Wall time per step is the frame's divided by its steps: in sim+render runs it carries the
  // rendering's share too; the solver's own GPU time per step is solver_gpu_step.
  f.step = {f.frame.median / steps_per_frame, f.frame.min / steps_per_frame, f.frame.max / steps_per_frame};
  std::vector<double> solver_step;
  for (double ms : r.solver_gpu_ms) solver_step.push_back(ms / steps_per_frame);
  f.solver_gpu_step = stats_of(solver_step);
  f.render_gpu = stats_of(r.render_gpu_ms);
  f.fps = f.frame.median > 0 ? 1000.0 / f.frame.median : 0.0;
  f.steps_per_second = f.fps * steps_per_frame;
  f.particles_per_second = f.steps_per_second * r.active_particles;
  return f;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The splat-adjoint pressure's passes are the solver's too, and so are the separable splat's
// deposit and spreads (and its potential's spreads), the active region's reductions, the mesh
// obstacles' field (all but drawing them into the view) and the floating bodies' passes.
bool is_solver_pass(const std::string& name) {
  const auto starts = [&name](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  return name == "liquid.splat" || name == "liquid.pressure" || name == "liquid.potential" || name == "liquid.grid" ||
         name == "liquid.particle" || name == "liquid.deposit" || starts("liquid.splat_spread_") ||
         starts("liquid.active_") || starts("liquid.potential_") || starts("liquid.body") ||
         (starts("liquid.mesh_") && name != "liquid.mesh_draw");
}

// The node, its renderer and a frame loop, as a host engine would hold them.
struct Bench {
  Bench(engine::vk::Context& context, const Configuration& c, const Options& o)
      : steps(o.steps_per_frame),
        node(context, c.scene,
             liquid::LiquidOptions{
                 .frames_in_flight = 1,
                 .max_steps_per_frame = o.steps_per_frame,
                 .grid_path = c.grid_path,
                 .active_region = !o.whole_grid}),
        loop(context) {
    if (c.mode == Mode::SimulationAndRender) {
      const bool composite = c.group == "composite";
      renderer = std::make_unique<liquid::LiquidRenderer>(
          context, node,
          liquid::RenderSettings{.width = o.width, .height = o.height, .fxaa = !composite, .composite = composite});
      camera = liquid::default_camera(node);
      if (composite) {
        using engine::vk::ImageDesc;
        host_color.emplace(context,
                           ImageDesc{engine::vk::ImageKind::Image2D, o.width, o.height, 1, c.composite_color,
                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT},
                           "host.color");
        host_depth.emplace(context,
                           ImageDesc{engine::vk::ImageKind::Image2D, o.width, o.height, 1, c.composite_depth,
                                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT},
                           "host.depth");
      }
    }
  }

  // One frame: the solver's steps, then the rendering if any (into the host's targets when
  // compositing).
  tools::FrameTime frame() {
    return loop.run([&](engine::graph::RenderGraph& graph) {
      const liquid::LiquidImages images = node.add_to(graph, steps);
      if (renderer && host_color)
        renderer->add_to(graph, images, camera,
                         {graph.import_image("host.color", *host_color), graph.import_image("host.depth", *host_depth)});
      else if (renderer)
        renderer->add_to(graph, images, camera);
    });
  }

  int steps;
  liquid::LiquidNode node;
  std::unique_ptr<liquid::LiquidRenderer> renderer;
  liquid::CameraView camera;
  std::optional<engine::vk::Image> host_color, host_depth;  // group "composite"
  tools::FrameLoop loop;
};

void record_frame(Result& r, const tools::FrameTime& time) {
  r.frame_ms.push_back(time.wall_ms);
  std::map<std::string, double> frame;
  double solver = 0.0, render = 0.0;
  for (const auto& t : time.passes) {
    if (!frame.count(t.name) && std::find(r.pass_order.begin(), r.pass_order.end(), t.name) == r.pass_order.end())
      r.pass_order.push_back(t.name);
    frame[t.name] += t.milliseconds;
    (is_solver_pass(t.name) ? solver : render) += t.milliseconds;
  }
  for (const auto& [name, ms] : frame) r.pass_ms[name].push_back(ms);
  r.solver_gpu_ms.push_back(solver);
  r.render_gpu_ms.push_back(render);
}

// The state after the timed frames: a benchmark of a blown-up simulation would be meaningless.
std::string check_stability(liquid::LiquidNode& node) {
  try {
    const liquid::Diagnostics d = node.diagnose();
    if (d.non_finite > 0) return std::to_string(d.non_finite) + " non-finite particles";
    return "stable";
  } catch (const liquid::SimulationError& error) {
    return error.what();
  }
}

}  // namespace

Result run_configuration(engine::vk::Context& context, const Configuration& c, const Options& o) {
  Result r;
  r.config = &c;
  const auto start = Clock::now();
  const VkDeviceSize held_before = context.memory_in_use();
  context.reset_memory_peak();
  Bench bench(context, c, o);
  r.setup_s = seconds_since(start);
  for (int i = 0; i < o.warmup; ++i) bench.frame();
  for (int i = 0; i < c.timed_frames; ++i) record_frame(r, bench.frame());
  r.active_particles = bench.node.active_particles();
  if (bench.node.dimension() == 3) r.grid_path = liquid::grid_path_name(simulation_of(bench.node).grid_layout().path);
  r.stability = check_stability(bench.node);
  r.device_memory_bytes = context.memory_peak() - held_before;
  r.total_s = seconds_since(start);
  return r;
}

}  // namespace tools::benchmark
