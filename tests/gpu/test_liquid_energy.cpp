// The physical targets of docs/physics.md on sizes that keep the suite quick (the full 10 s runs
// are liquid_validate's): still water stays still, level and of constant volume; a dam break gains
// no mechanical energy; the collapsing column's front follows Martin and Moyce (1952); and the
// chapter's pressure gradient, the cause of the energy growth, does measurable work on still water.
#include "liquid/node.h"
#include "liquid/validation.h"
#include "tests/gpu/liquid_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

struct Sample {
  double t, kinetic, potential, mechanical, volume, front, level_spread;
};

double spread(const std::vector<double>& heights) {
  double sum = 0.0;
  int n = 0;
  for (double h : heights)
    if (h >= 0.0) sum += h, ++n;
  double worst = 0.0;
  for (double h : heights)
    if (h >= 0.0) worst = std::max(worst, std::abs(h - sum / n));
  return worst;
}

// Runs `seconds`, sampling every `every` steps.
std::vector<Sample> run_sampled(liquid::LiquidNode& node, double seconds, int every) {
  std::vector<Sample> samples;
  const int total = int(std::lround(seconds / double(node.setup().time_step)));
  for (int done = 0; done < total;) {
    const int n = std::min(every, total - done);
    test::run_steps(node, n);
    done += n;
    const liquid::ParticleSnapshot p = node.read_particles();
    const liquid::Diagnostics d = node.diagnose(p);
    const std::vector<float> rho = node.read_density_ratio();
    const std::vector<double> heights = liquid::surface_heights(rho, node.setup());
    samples.push_back({d.time, d.kinetic_energy, d.potential_energy, d.mechanical_energy,
                       liquid::volume_under_surface(heights, node.setup()), liquid::surge_front(p), spread(heights)});
  }
  return samples;
}

// rest_pool_2d at twice its cell size (same depth, same acoustic CFL): 1,000 particles on 32².
liquid::Scene coarse_pool() {
  liquid::Scene s = test::shipped_scene("rest_pool_2d");
  s.grid_resolution = 32;
  s.particle_spacing *= 2.0f;
  s.time_step *= 2.0f;
  s.substeps = (s.substeps + 1) / 2;
  return s;
}

}  // namespace

TEST_CASE("still water stays still, level and of constant volume", "[gpu][liquid][physics][energy]") {
  liquid::LiquidNode node(test::gpu(), coarse_pool());
  const std::vector<Sample> s = run_sampled(node, 3.0, node.substeps());
  const double pe0 = s.front().potential, h = node.setup().cell_size;
  double early = 0.0, late = 0.0, worst_level = 0.0, worst_volume = 0.0;
  for (const Sample& x : s) {
    if (x.t >= 1.0 && x.t < 2.0) early = std::max(early, x.kinetic);
    if (x.t >= 2.0) late = std::max(late, x.kinetic);
    if (x.t >= 1.0) worst_level = std::max(worst_level, x.level_spread);
    worst_volume = std::max(worst_volume, std::abs(x.volume / s.front().volume - 1.0));
  }
  INFO("PE(0) " << pe0 << " J, max KE 1-2 s " << early << " J, 2-3 s " << late << " J, worst level deviation "
                << worst_level / h << " cells, worst volume change " << worst_volume);
  CHECK(early < 5e-4 * pe0);  // the target: below 0.05 % of the potential energy from 1 s on
  CHECK(late <= early);       // and not growing
  CHECK(worst_level < h);     // the surface within one cell everywhere
  CHECK(worst_volume < 0.01);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("the chapter's pressure gradient does work on still water, the splat-adjoint one does not",
          "[gpu][liquid][physics][energy]") {
  // Pure PIC, so no FLIP noise can carry energy: what the pool gains is work done by the pressure
  // force itself (docs/physics.md). Over the second second the chapter's force raises the pool's
  // potential energy; the splat-adjoint force, the gradient of an energy, lets it only settle.
  auto gain = [](liquid::PressureForce force) {
    liquid::Scene scene = coarse_pool();
    scene.pic_ratio = 1.0f;
    scene.pressure_force = force;
    liquid::LiquidNode node(test::gpu(), scene);
    const std::vector<Sample> s = run_sampled(node, 2.0, node.substeps());
    double at_one = 0.0;
    for (const Sample& x : s)
      if (x.t <= 1.0 + 1e-6) at_one = x.mechanical;
    return (s.back().mechanical - at_one) / s.front().potential;
  };
  const double chapter = gain(liquid::PressureForce::Chapter);
  const double adjoint = gain(liquid::PressureForce::SplatAdjoint);
  INFO("gain of KE + PE from 1 s to 2 s, share of PE(0): chapter " << chapter << ", splat-adjoint " << adjoint);
  CHECK(chapter > 1e-3);
  CHECK(adjoint < 1e-4);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("a dam break gains no mechanical energy and keeps its volume", "[gpu][liquid][physics][energy]") {
  // dam_break_2d at twice its cell size: 4,000 particles on 63x38, 2 s.
  liquid::Scene scene = test::shipped_scene("dam_break_2d");
  scene.grid_resolution = 63;
  scene.particle_spacing *= 2.0f;
  scene.time_step *= 2.0f;
  scene.substeps = scene.substeps / 2;
  liquid::LiquidNode node(test::gpu(), scene);
  const std::vector<Sample> s = run_sampled(node, 2.0, node.substeps());
  double impact = s.back().t;
  for (const Sample& x : s)
    if (x.front >= node.setup().domain.x - 2.0 * node.setup().cell_size) {
      impact = x.t;
      break;
    }
  std::vector<double> t, e;
  for (const Sample& x : s) t.push_back(x.t), e.push_back(x.mechanical);
  const double pe0 = s.front().potential;
  const double gain = liquid::max_gain_in_window(t, e, impact, 1.0);
  INFO("impact at " << impact << " s; largest gain in 1 s after it " << gain << " J of PE(0) " << pe0
                    << " J; KE + PE " << e.front() << " -> " << e.back() << " J");
  CHECK(impact < 1.0);
  CHECK(gain < 0.01 * pe0);
  CHECK(e.back() < e.front());
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("the collapsing column's front follows Martin and Moyce and converges", "[gpu][liquid][physics][energy]") {
  const liquid::Scene base = test::shipped_scene("column_2d");
  const double a = base.fluid_blocks.at(0).max.x, g = 9.81, scale = std::sqrt(2.0 * g / a);
  auto front_error = [&](double spacing_factor) {
    liquid::Scene scene = base;
    scene.particle_spacing *= float(spacing_factor);
    scene.grid_resolution = int(std::lround(*base.grid_resolution / spacing_factor));
    scene.time_step *= float(spacing_factor);
    scene.substeps = int(std::lround(base.substeps / spacing_factor));
    liquid::LiquidNode node(test::gpu(), scene);
    const std::vector<Sample> s = run_sampled(node, 3.4 / scale, int(std::lround(0.0025 / scene.time_step)));
    std::vector<double> T{0.0}, Z{1.0};
    for (const Sample& x : s) T.push_back(x.t * scale), Z.push_back(x.front / a);
    return liquid::compare_front(T, Z);
  };
  const liquid::FrontError shipped = front_error(1.0);  // spacing 2 mm, the scene as shipped
  const liquid::FrontError coarse = front_error(2.0);   // 4 mm
  INFO("|Z - Z_exp| / Z_exp at 2 mm: mean " << shipped.mean << ", max " << shipped.max << " over " << shipped.points
                                            << " points; at 4 mm: mean " << coarse.mean << ", max " << coarse.max);
  CHECK(shipped.points >= 13);
  CHECK(shipped.mean < 0.05);
  CHECK(shipped.max < 0.10);
  CHECK(shipped.mean < coarse.mean);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
