// The physical targets of docs/physics.md on sizes that keep the suite quick (the full 10 s runs
// are liquid_validate's): still water stays still, level and of constant volume; a dam break gains
// no mechanical energy; the collapsing column's front follows Martin and Moyce (1952); and the
// chapter's pressure gradient, the cause of the energy growth, does measurable work on still water.
#include "liquid/analysis/oscillation.h"
#include "liquid/analysis/still_water.h"
#include "liquid/analysis/travelling_wave.h"
#include "liquid/analysis/validation.h"
#include "liquid/node.h"
#include "liquid/physics/time_step.h"
#include "liquid/solver/simulation.h"
#include "tests/gpu/liquid_helpers.h"
#include "tests/support/meshes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
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
  const int total = int(std::lround(seconds / double(simulation_of(node).setup().time_step)));
  for (int done = 0; done < total;) {
    const int n = std::min(every, total - done);
    test::run_steps(node, n);
    done += n;
    const liquid::ParticleSnapshot p = node.read_particles();
    const liquid::Diagnostics d = node.diagnose(p);
    const std::vector<float> rho = node.read_density_ratio();
    const std::vector<double> heights = liquid::surface_heights(rho, simulation_of(node).setup());
    samples.push_back({d.time, d.kinetic_energy, d.potential_energy, d.mechanical_energy,
                       liquid::volume_under_surface(heights, simulation_of(node).setup()), liquid::surge_front(p), spread(heights)});
  }
  return samples;
}

// rest_pool_2d at twice its cell size (same depth, same acoustic CFL): 1,000 particles on 32².
liquid::Scene coarse_pool() {
  const liquid::Scene base = test::shipped_scene("rest_pool_2d");
  return liquid::scene_at_spacing(base, 2.0 * base.particle_spacing);
}

// column_2d at `spacing_factor` times its particle spacing (grid, step and PIC reference step with it).
liquid::Scene column_at(double spacing_factor) {
  const liquid::Scene base = test::shipped_scene("column_2d");
  return liquid::scene_at_spacing(base, base.particle_spacing * spacing_factor);
}

// The column's surge front against Martin and Moyce, sampled every 2.5 ms up to T = 3.4, at once
// and after the experiment's release (liquid::compare_front_released).
liquid::ReleasedFront released_column_front(const liquid::Scene& scene) {
  const double a = scene.fluid_blocks.at(0).max.x, g = 9.81, scale = std::sqrt(2.0 * g / a);
  liquid::LiquidNode node(test::gpu(), scene);
  const std::vector<Sample> s =
      run_sampled(node, 3.4 / scale, std::max(1, int(std::lround(liquid::k_front_sample_period_s / scene.time_step))));
  std::vector<double> T{0.0}, Z{1.0};
  for (const Sample& x : s) T.push_back(x.t * scale), Z.push_back(x.front / a);
  return liquid::compare_front_released(T, Z);
}

// The same with the start at once, under the equation of state with its former PIC share.
liquid::FrontError column_front(const liquid::Scene& scene) {
  return released_column_front(test::under_equation_of_state(scene, 0.05f)).at_once;
}

}  // namespace

TEST_CASE("still water stays still, level and of constant volume", "[gpu][liquid][physics][energy]") {
  liquid::LiquidNode node(test::gpu(), coarse_pool());
  const std::vector<Sample> s = run_sampled(node, 3.0, node.substeps());
  const double pe0 = s.front().potential, h = simulation_of(node).setup().cell_size;
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
    liquid::Scene scene = test::under_equation_of_state(coarse_pool(), 1.0f);
    scene.pressure_force = force;
    // The same step for both forces: the chapter's regime would refuse the long one.
    scene.allow_unstable_time_step = true;
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
  scene.pic_ratio_reference_step.value() *= 2.0f;
  scene.substeps = scene.substeps / 2;
  liquid::LiquidNode node(test::gpu(), scene);
  const std::vector<Sample> s = run_sampled(node, 2.0, node.substeps());
  double impact = s.back().t;
  for (const Sample& x : s)
    if (x.front >= simulation_of(node).setup().domain.x - 2.0 * simulation_of(node).setup().cell_size) {
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

// The shipped column (the pressure projection, PIC 0.002) after the experiment's release, as
// liquid_validate holds it (docs/physics.md, "The release in the target"; measured 2026-12-07 with
// 4 iterations: see there); the equation of state's at once, and converging.
TEST_CASE("the collapsing column's front follows Martin and Moyce and converges", "[gpu][liquid][physics][energy]") {
  const liquid::ReleasedFront projection = released_column_front(column_at(1.0));  // 2 mm, as shipped
  INFO("shipped, after a release of T0 = " << projection.delay << ": mean " << projection.released.mean << ", max "
                                           << projection.released.max << "; at once: mean " << projection.at_once.mean);
  CHECK(projection.released.points == liquid::k_front_points);
  CHECK(projection.released.mean < 0.05);
  CHECK(projection.released.max < 0.10);
  const liquid::FrontError shipped = column_front(column_at(1.0));  // spacing 2 mm
  const liquid::FrontError coarse = column_front(column_at(2.0));   // 4 mm
  INFO("equation of state, |Z - Z_exp| / Z_exp at 2 mm: mean " << shipped.mean << ", max " << shipped.max << " over "
                                                               << shipped.points << " points; at 4 mm: mean "
                                                               << coarse.mean << ", max " << coarse.max);
  CHECK(shipped.points == liquid::k_front_points);
  CHECK(shipped.mean < 0.05);
  CHECK(shipped.max < 0.10);
  CHECK(shipped.mean < coarse.mean);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("with the PIC blend per second the column's front keeps its place at 8 times the step, blended per step "
          "it runs ahead",
          "[gpu][liquid][physics][energy]") {
  // column_2d at 4 mm under the equation of state (column_front): at the chapter's step (its
  // reference step), at the shipped 8 times that step, and at 8 times the step with r per step (the
  // chapter's blend). Measured (2026-12-07): Z at T = 3.33 of
  // 3.40, 3.59 and 4.16 (docs/physics.md, "The PIC blend per second", has the 2 mm figures).
  liquid::Scene chapter_step = column_at(2.0);
  chapter_step.time_step = chapter_step.pic_ratio_reference_step.value();
  const liquid::Scene shipped = column_at(2.0);
  liquid::Scene per_step = shipped;
  per_step.pic_ratio_reference_step.reset();
  per_step.allow_unstable_time_step = true;  // the long step in the chapter's regime, to show what it does
  const double reference = column_front(chapter_step).model.back();
  const double rate = column_front(shipped).model.back();
  const double chapter_blend = column_front(per_step).model.back();
  INFO("Z at T = 3.33: chapter's step " << reference << ", 8 times the step " << rate << ", the same blended per step "
                                        << chapter_blend);
  CHECK(std::abs(rate - reference) < 0.06 * reference);
  CHECK(chapter_blend - reference > 3.0 * std::abs(rate - reference));
  REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("adaptive steps keep stable a dam break whose fixed step explodes", "[gpu][liquid][physics][time_step]") {
  // dam_break_2d with a step 4 times the shipped one (3.6 ms, an acoustic CFL of about 5): as a
  // fixed step it explodes within 100 steps (0.36 s); with "adaptive_time_step" at the acoustic
  // CFL of its regime (liquid/physics/time_step.h) the same scene takes the CFL step after every batch
  // (about 7e-4 s here, at most that 3.6 ms) and covers those 0.36 s intact, its clock the sum of
  // the steps it took.
  liquid::Scene scene = test::under_equation_of_state(test::shipped_scene("dam_break_2d"), 0.05f);
  scene.time_step *= 4.0f;
  scene.allow_unstable_time_step = true;  // as a fixed step, refused by make_setup: the point here
  const double covered = 100 * double(scene.time_step);
  {
    liquid::LiquidNode fixed(test::gpu(), scene);
    CHECK_THROWS_AS(test::run_steps(fixed, 100), liquid::SimulationError);
  }
  scene.adaptive_time_step = liquid::AdaptiveTimeStep{float(liquid::k_acoustic_cfl_smoothed), 0.4f};
  liquid::LiquidNode node(test::gpu(), scene);
  liquid::Diagnostics at_rest;
  at_rest.max_density_ratio = 1.0f;  // the first batch: the CFL step of the liquid at rest
  CHECK(node.time_step() ==
        Approx(liquid::cfl_time_step(simulation_of(node).setup(), *scene.adaptive_time_step, at_rest, scene.time_step)));
  liquid::Diagnostics d = node.diagnose();
  double clock = 0.0, smallest = 1.0, largest = 0.0;
  while (node.time() < covered) {
    const double dt = node.adapt_time_step(d);
    REQUIRE(dt == Approx(liquid::cfl_time_step(simulation_of(node).setup(), *scene.adaptive_time_step, d, scene.time_step)));
    REQUIRE(dt <= scene.time_step);
    smallest = std::min(smallest, dt);
    largest = std::max(largest, dt);
    const int steps = node.substeps();
    d = test::run_steps(node, steps);  // throws SimulationError if the run blows up
    clock += steps * double(float(dt));
    REQUIRE(d.time_step == Approx(dt));
  }
  INFO("steps from " << smallest << " to " << largest << " s over " << node.time() << " s in " << node.step_count()
                     << " steps; max rho/rho0 " << d.max_density_ratio);
  CHECK(node.time() == Approx(clock).epsilon(1e-9));
  CHECK(largest < 0.3 * scene.time_step);  // the acoustic bound, far below the scene's step
  CHECK(smallest < largest);                // and it moves with the state
  test::require_conserved(node, d, simulation_of(node).setup().initial_particles);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

namespace {

// The first sloshing mode of liquid/analysis/oscillation.h's tank with `physics`'s liquid on `cells`
// along the tank, for two periods: its period and damping.
liquid::Oscillation sloshing_of(const liquid::Scene& physics, liquid::GridPath path, int dimension, int cells) {
  const liquid::SloshingTank tank = liquid::sloshing_tank(dimension, cells);
  const liquid::Scene scene = liquid::sloshing_scene(physics, tank);
  liquid::LiquidNode node(dimension == 3 ? test::gpu_for(path) : test::gpu(), scene,
                          dimension == 3 ? test::options_for(path) : liquid::LiquidOptions{});
  const double period = liquid::sloshing_period(tank.length, tank.depth, glm::length(scene.gravity));
  const double dt = simulation_of(node).setup().time_step;
  const int every = std::max(1, int(std::lround(period / 40.0 / dt)));
  std::vector<double> t, x;
  for (int done = 0; done * dt < 2.0 * period; done += every) {
    test::run_steps(node, every);
    t.push_back(node.time());
    x.push_back(liquid::centre_of_mass_x(node.read_particles()));
  }
  return liquid::measure_oscillation(t, x, 0.5 * tank.length);
}

// rest_pool_2d's regime under the equation of state with point sprites and the given transfer.
liquid::Oscillation sloshing_with(liquid::Transfer transfer, liquid::GridPath path, int dimension, int cells) {
  liquid::Scene physics = test::under_equation_of_state(test::shipped_scene("rest_pool_2d"), 0.1f);
  physics.splat = liquid::SplatMode::PointSprite;
  physics.transfer = transfer;
  return sloshing_of(physics, path, dimension, cells);
}

}  // namespace

// docs/physics.md, "Where sloshing loses its energy": the chapter's transfer loses the surface's
// motion at every step and the wave's period stretches as it dies; the affine one keeps a linear
// field through the transfer. Measured 2026-12-06 over these two periods: 2D the chapter's period
// +14 % and zeta 0.18, the affine's -0.9 % and 0.084. 3D at 32 cells, since the tank is filled at
// rest density across its width (2026-12-07), +23 % and 0.37 against +28 % and 0.060: the period is
// checked in 2D only (started 9 % below rest density, as before, the 3D tank gave -30 % and -2.1 %).
TEST_CASE("the affine transfer keeps a sloshing tank's period and damps it half as much as the chapter's",
          "[gpu][liquid][physics][affine]") {
  using liquid::Transfer;
  // 3D at half the cells (six across) on the atlas path, the one whose splat tiles need the most care.
  for (const auto& [dimension, cells, path] :
       {std::tuple{2, 64, liquid::GridPath::VertexLayer}, std::tuple{3, 32, liquid::GridPath::Atlas}}) {
    INFO(dimension << "D, " << cells << " cells");
    const liquid::Oscillation chapter = sloshing_with(Transfer::PicFlip, path, dimension, cells);
    const liquid::Oscillation affine = sloshing_with(Transfer::Affine, path, dimension, cells);
    const double theory = liquid::sloshing_period(0.5, 0.1, 9.81);
    INFO("period error: chapter " << chapter.period / theory - 1.0 << ", affine " << affine.period / theory - 1.0
                                  << "; zeta: chapter " << chapter.damping_ratio << ", affine " << affine.damping_ratio);
    if (dimension == 2) CHECK(std::abs(affine.period / theory - 1.0) < 0.04);
    CHECK(affine.damping_ratio < 0.6 * chapter.damping_ratio);
    CHECK(affine.damping_ratio > 0.0);  // and no energy from nowhere
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// docs/physics.md, "A pressure projection": the pressure solved so that the velocity has no
// divergence, instead of the equation of state's, keeps the slow waves; with a PIC share of 0.002
// per reference step the wave keeps its period and loses a few hundredths of its amplitude a period.
// Measured 2026-12-06 over these two periods: 2D at 64 cells +0.6 % and zeta 0.013.
TEST_CASE("the pressure projection keeps a sloshing tank's period and its motion", "[gpu][liquid][physics][projection]") {
  liquid::Scene physics = test::shipped_scene("rest_pool_2d");  // the separable splat
  physics.projection_iterations = 40;
  physics.pic_ratio = 0.002f;
  for (const auto& [dimension, cells, path] :
       {std::tuple{2, 64, liquid::GridPath::VertexLayer}, std::tuple{3, 64, liquid::GridPath::Atlas}}) {
    INFO(dimension << "D, " << cells << " cells");
    const liquid::Oscillation wave = sloshing_of(physics, path, dimension, cells);
    const double theory = liquid::sloshing_period(0.5, 0.1, 9.81);
    INFO("period error " << wave.period / theory - 1.0 << ", zeta " << wave.damping_ratio << " over "
                         << wave.half_cycles << " half cycles");
    CHECK(std::abs(wave.period / theory - 1.0) < 0.04);
    CHECK(wave.damping_ratio < 0.03);
    CHECK(wave.damping_ratio > 0.0);  // and no energy from nowhere
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// docs/physics.md, "The surface's nearest distance": the pulse's modes are 0.2 to 0.3 of a 64-cell
// tank's cell high, and where the ghost fluid's surface distance was clamped (at a quarter cell)
// the pressure stopped following their height: they ran 11 to 20 % slow. Measured 2026-12-07 over
// these two first-mode periods (liquid_validate --quick): +1.5, +2.1 and +3.3 %, zeta 0.011, 0.007
// and 0.014; with the quarter-cell clamp +20, +12 and +11 %.
TEST_CASE("under the pressure projection a low pulse keeps the periods of its modes", "[gpu][liquid][physics][projection]") {
  liquid::Scene physics = test::shipped_scene("rest_pool_2d");
  physics.projection_iterations = 40;
  physics.pic_ratio = 0.002f;
  const liquid::TravellingPulse pulse = liquid::travelling_pulse(2, 64);
  const liquid::Scene scene = liquid::travelling_pulse_scene(physics, pulse);
  liquid::LiquidNode node(test::gpu(), scene);
  const double g = glm::length(scene.gravity), length = pulse.tank.length;
  const double depth = liquid::settled_depth(scene, size_t(simulation_of(node).setup().initial_particles));
  const double dt = simulation_of(node).setup().time_step;
  const int every = std::max(1, int(std::lround(liquid::tank_mode_period(length, depth, g, 3) / 40.0 / dt)));
  const double area = liquid::particle_section(scene);
  std::vector<double> t;
  std::vector<std::vector<double>> modes(3);
  for (int done = 0; done * dt < 2.0 * liquid::tank_mode_period(length, depth, g, 1); done += every) {
    test::run_steps(node, every);
    t.push_back(node.time());
    const liquid::ParticleSnapshot particles = node.read_particles();
    for (int n = 1; n <= 3; ++n) modes[size_t(n - 1)].push_back(liquid::tank_mode_amplitude(particles, n, length, area));
  }
  for (int n = 1; n <= 3; ++n) {
    const liquid::Oscillation m = liquid::measure_oscillation(t, modes[size_t(n - 1)], 0.0);
    const double error = m.period / liquid::tank_mode_period(length, depth, g, n) - 1.0;
    INFO("mode " << n << ": period error " << error << ", zeta " << m.damping_ratio << " over " << m.half_cycles
                 << " half cycles");
    CHECK(m.half_cycles >= 3);
    CHECK(std::abs(error) < 0.05);
    CHECK(m.damping_ratio < 0.03);
    CHECK(m.damping_ratio > 0.0);  // and no energy from nowhere
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

namespace {

// The sloshing tank filled flat (liquid_validate's still water) with `physics`'s liquid: its surface
// from the particles at `times`, the density profile below it at the last, and the depth the
// particles fill at rest density.
struct StillWater {
  std::vector<double> levels;
  liquid::DensityProfile profile;
  double rest_depth = 0.0;
};
StillWater still_water(const liquid::Scene& physics, int dimension, liquid::GridPath path, std::vector<double> times) {
  const liquid::SloshingTank tank = liquid::sloshing_tank(dimension, 64);
  const double still = liquid::tank_still_depth(physics, tank);
  const liquid::Scene scene = liquid::tank_scene(physics, tank, [&](double) { return still; });
  liquid::LiquidNode node(dimension == 3 ? test::gpu_for(path) : test::gpu(), scene,
                          dimension == 3 ? test::options_for(path) : liquid::LiquidOptions{});
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  StillWater out;
  out.rest_depth = liquid::settled_depth(scene, size_t(setup.initial_particles));
  int done = 0;
  for (double t : times) {
    const int to = int(std::lround(t / setup.time_step));
    test::run_steps(node, to - done);
    done = to;
    out.levels.push_back(liquid::particle_surface_level(node.read_particles(), tank.length, scene.particle_spacing));
  }
  out.profile = liquid::density_profile(node.read_density_ratio(), setup, out.levels.back());
  return out;
}
std::vector<double> still_levels(const liquid::Scene& physics, int dimension, liquid::GridPath path,
                                 std::vector<double> times) {
  return still_water(physics, dimension, path, std::move(times)).levels;
}

// The same in rest_pool_2d's regime under the equation of state with the given position correction.
std::vector<double> still_levels(double correction, int dimension, liquid::GridPath path, std::vector<double> times) {
  liquid::Scene physics = test::under_equation_of_state(test::shipped_scene("rest_pool_2d"), 0.1f);
  physics.position_correction = float(correction);
  return still_levels(physics, dimension, path, std::move(times));
}

}  // namespace

// docs/physics.md, "Still water that keeps its volume": without the correction the top layers of a
// pool at rest sink into the gaps of the layers below and the surface creeps down; with it they
// stay. Measured 2026-12-06 from 1 s to 4 s (beta 0.1): 2D 1.39 mm down without, 0.35 mm with;
// 3D (the atlas path) 1.42 and 0.06 mm; the depth is about 0.1 m.
TEST_CASE("the position correction keeps a pool's surface where it settled", "[gpu][liquid][physics][still]") {
  for (const auto& [dimension, path] : {std::tuple{2, liquid::GridPath::VertexLayer}, std::tuple{3, liquid::GridPath::Atlas}}) {
    INFO(dimension << "D");
    const std::vector<double> off = still_levels(0.0, dimension, path, {1.0, 4.0});
    const std::vector<double> on = still_levels(0.1, dimension, path, {1.0, 4.0});
    const double depth = 0.1;
    INFO("surface drop from 1 s to 4 s: " << 1e3 * (off[0] - off[1]) << " mm without, " << 1e3 * (on[0] - on[1])
                                          << " mm with the correction; at 1 s " << 1e3 * off[0] << " and "
                                          << 1e3 * on[0] << " mm");
    CHECK(std::abs(on[0] - on[1]) < 0.005 * depth);  // the target: 0.5 % of the depth
    CHECK(off[0] - off[1] > 0.01 * depth);           // what it corrects
    CHECK(on[0] > off[0]);                           // the top layers not packed at 1 s either
  }
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// docs/physics.md, "A pressure projection": the projection's pressure holds the surface cell's
// particles too (its gradient across the surface reaches the air cell above), so a pool at rest
// keeps its level and its top layer; its density correction spreads the particles to rest density,
// so the liquid below the surface is not denser at the bottom and fills the depth its mass makes at
// rest density. Measured 2026-12-07 (1 s, 3 s): without the correction 97.27 mm at both, the depth
// at rest density 98.29 mm, the density slope 2.8 times the pressure law's; with it (and the
// lattice started at rest density, not compressed as the equation of state would have it) 98.36
// and 98.37 mm, the slope -0.0009 /m against the law's 0.20 /m.
TEST_CASE("under the pressure projection a pool at rest keeps its level and its density", "[gpu][liquid][physics][projection][still]") {
  liquid::Scene physics = test::shipped_scene("rest_pool_2d");
  physics.projection_iterations = 40;
  physics.pic_ratio = 0.002f;
  const StillWater still = still_water(physics, 2, liquid::GridPath::VertexLayer, {1.0, 3.0});
  const std::vector<double>& levels = still.levels;
  const double depth = 0.1;
  INFO("surface " << 1e3 * levels[0] << " mm at 1 s, " << 1e3 * levels[1] << " mm at 3 s, "
                  << 1e3 * still.rest_depth << " mm at rest density; density slope " << still.profile.slope
                  << " /m over " << still.profile.rows << " rows, the pressure law's " << still.profile.hydrostatic);
  CHECK(std::abs(levels[0] - levels[1]) < 0.005 * depth);             // the target: 0.5 % of the depth
  CHECK(std::abs(levels[1] - still.rest_depth) < 0.005 * depth);      // neither packed nor spread
  REQUIRE(still.profile.rows >= 4);
  CHECK(std::abs(still.profile.slope) < 0.1 * still.profile.hydrostatic);  // the target: incompressible
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// liquid/solver/projection_start.h: the projection starts from still water's pressure, so with as
// few as 4 iterations a step a pool let go at rest stays at rest from its first step. Measured
// 2026-12-07 over the first 0.3 s: at most 2.7e-4 J of motion (of 54.9 J of potential energy);
// started from p = 0, the pool fell onto itself and rang with up to 0.43 J, and its volume
// overshot by 6 %.
TEST_CASE("under the pressure projection with 4 iterations a pool let go at rest does not fall onto itself",
          "[gpu][liquid][physics][projection][still]") {
  liquid::Scene scene = test::shipped_scene("rest_pool_2d");
  scene.projection_iterations = 4;
  scene.pic_ratio = 0.002f;
  liquid::LiquidNode node(test::gpu(), scene);
  const int count = node.active_particles();
  const double potential = node.diagnose().potential_energy;
  double most = 0.0;
  liquid::Diagnostics d;
  for (int i = 0; i < 9; ++i) {  // 0.3 s
    d = test::run_steps(node, 25);
    most = std::max(most, d.kinetic_energy);
  }
  INFO("most kinetic energy " << most << " J over " << node.time() << " s, potential energy " << potential << " J");
  CHECK(most < 2e-5 * potential);
  test::require_conserved(node, d, count);
  REQUIRE_NO_VALIDATION_MESSAGES();
}

// docs/physics.md, "Static obstacles in the projection": a cell inside a static obstacle is solid to
// the projection (its faces carry the obstacle's velocity and drop out of the rows, as a wall's),
// and the fill carves only the particles' skin around it, so a pool around a box on the floor, a
// post through its surface and a mesh sphere under it stays at rest. Measured 2026-12-07: the
// surface 147.139 mm at 0.5 s and 147.143 at 2 s, 1.6e-5 J of motion left, the fastest particle at
// 0.022 m/s; with the solid cells' ghost pressure not continued upward (the walls' rule), the
// liquid under the sphere and the post's foot kept 3.3e-3 J and 0.22 m/s.
TEST_CASE("under the pressure projection a pool around static obstacles stays at rest",
          "[gpu][liquid][physics][projection][obstacles]") {
  liquid::Scene scene = test::shipped_scene("rest_pool_2d");  // 0.15 m deep
  scene.projection_iterations = 40;
  scene.pic_ratio = 0.002f;
  liquid::Obstacle box, post;
  box.shape = post.shape = liquid::ObstacleShape::Box;
  box.center = glm::vec3(0.1f, 0.04f, 0.0f), box.half_extent = glm::vec3(0.05f, 0.04f, 0.0f);
  post.center = glm::vec3(0.4f, 0.15f, 0.0f), post.half_extent = glm::vec3(0.03f, 0.1f, 0.0f);
  scene.obstacles = {box, post, test::mesh_obstacle_of(test::icosphere(0.03f, 3), glm::vec3(0.25f, 0.06f, 0.0f))};
  liquid::LiquidNode node(test::gpu(), scene);
  const liquid::SimulationSetup& setup = simulation_of(node).setup();
  // The surface over the open water between the box's left edge and the post: the mean of the
  // highest particle of each strip two spacings wide.
  const auto level = [&] {
    const liquid::ParticleSnapshot particles = node.read_particles();
    const double s = scene.particle_spacing, from = 0.06, to = 0.36;
    std::vector<double> top(size_t((to - from) / (2.0 * s)), 0.0);
    for (const glm::vec4& p : particles.positions) {
      const double strip = (double(p.x) - from) / (2.0 * s);
      if (strip >= 0.0 && strip < double(top.size())) top[size_t(strip)] = std::max(top[size_t(strip)], double(p.y));
    }
    double sum = 0.0;
    for (double y : top) sum += y;
    return sum / double(top.size());
  };
  const int half_second = int(std::lround(0.5 / setup.time_step));
  liquid::Diagnostics d = test::run_steps(node, half_second);
  test::require_conserved(node, d, setup.initial_particles);
  const double settled = level();
  d = test::run_steps(node, 3 * half_second);
  test::require_conserved(node, d, setup.initial_particles);
  const double end = level();
  INFO("surface " << 1e3 * settled << " mm at 0.5 s, " << 1e3 * end << " mm at 2 s; kinetic energy " << d.kinetic_energy
                  << " J, fastest particle " << d.max_speed << " m/s, potential energy " << d.potential_energy << " J");
  CHECK(std::abs(end - settled) < 0.005 * 0.15);  // the still-water target: 0.5 % of the depth
  CHECK(d.kinetic_energy < 5e-4);
  CHECK(d.max_speed < 0.1f);
  REQUIRE_NO_VALIDATION_MESSAGES();
}
