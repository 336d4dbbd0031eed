// The sloshing measurements with no GPU: the first mode's period against the limits linear theory
// reduces to, a damped oscillation's period and damping ratio recovered from samples, the sloshing
// tank's scene, and the energy budget's terms on steps whose every term is known.
#include "liquid/analysis/energy_budget.h"
#include "liquid/analysis/oscillation.h"
#include "liquid/physics/setup.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace liquid;

TEST_CASE("the sloshing period tends to deep water's and shallow water's", "[oscillation]") {
  const double g = 9.81, L = 0.5, k = std::numbers::pi / L;
  CHECK(sloshing_period(L, 100.0 * L, g) == Approx(2.0 * std::numbers::pi / std::sqrt(g * k)).epsilon(1e-9));
  // Shallow: omega = k sqrt(g h), so T = 2 L / sqrt(g h), to O((k h)^2).
  const double h = 0.002;
  CHECK(sloshing_period(L, h, g) == Approx(2.0 * L / std::sqrt(g * h)).epsilon(1e-4));
}

TEST_CASE("a damped oscillation's period and damping ratio are recovered from its samples", "[oscillation]") {
  for (const double zeta : {0.0, 0.005, 0.03, 0.2}) {
    INFO("zeta " << zeta);
    const double period = 1.07, omega_n = 2.0 * std::numbers::pi / period / std::sqrt(1.0 - zeta * zeta);
    const double omega_d = 2.0 * std::numbers::pi / period;
    std::vector<double> t, y;
    for (int i = 0; i <= 4 * 60; ++i) {
      t.push_back(i * period / 60.0);
      y.push_back(0.25 + 0.01 * std::exp(-zeta * omega_n * t.back()) * std::cos(omega_d * t.back()));
    }
    const Oscillation o = measure_oscillation(t, y, 0.25);
    // Four periods: seven half cycles between crossings, or those before the peaks fall below a tenth.
    CHECK(o.half_cycles == (zeta < 0.1 ? 7 : 3));
    CHECK(o.period == Approx(period).epsilon(0.003));
    CHECK(o.damping_ratio == Approx(zeta).margin(0.003));
  }
  const std::vector<double> t{0.0, 1.0, 2.0}, flat{1.0, 1.0, 1.0};
  CHECK(std::isnan(measure_oscillation(t, flat, 0.0).period));
}

TEST_CASE("the sloshing tank holds the still volume with its surface as the first mode", "[oscillation]") {
  const Scene physics = test_scenes::scene_of("rest_pool_2d.json");
  SloshingTank tank;
  tank.cells_along = 64;
  const Scene scene = sloshing_scene(physics, tank);
  CHECK(scene.grid_resolution == 64);
  CHECK(scene.domain.x == Approx(tank.length));
  double area = 0.0;
  for (const FluidBlock& b : scene.fluid_blocks) area += double(b.max.x - b.min.x) * double(b.max.y - b.min.y);
  // The surface rounded to whole layers: within half a layer of L h.
  CHECK(area == Approx(tank.length * tank.depth).margin(0.5 * tank.length * scene.particle_spacing));
  const double rise = scene.fluid_blocks.front().max.y - scene.fluid_blocks.back().max.y;
  CHECK(rise == Approx(2.0 * tank.amplitude).margin(scene.particle_spacing));
  // The rest pool's regime: its particles per cell and its acoustic CFL.
  const double base_cell = 0.5 / 64.0;
  CHECK(scene.particle_spacing / (tank.length / 64.0) == Approx(physics.particle_spacing / base_cell));
  const SimulationSetup setup = make_setup(scene, DeviceLimits{});
  CHECK(setup.grid_cells.x == 64);

  tank.dimension = 3;
  tank.width = 0.05;
  const Scene scene_3d = sloshing_scene(physics, tank);
  CHECK(scene_3d.dimension == 3);
  CHECK(scene_3d.fluid_blocks.front().max.z == Approx(0.05));
}

namespace {

// A 2D setup of 8 x 8 cells of 0.1 m whose grids hold liquid everywhere with velocities u and u'.
struct UniformGrid {
  SimulationSetup setup;
  std::vector<glm::vec4> splat, velocity;
  UniformGrid(glm::vec3 u_old, glm::vec3 u_new) {
    setup.dimension = 2;
    setup.grid_cells = glm::ivec3(8, 8, 1);
    setup.cell_size = 0.1f;
    setup.time_step = 0.01f;
    setup.particle_mass = 2.0f;
    setup.gravity = glm::vec3(0.0f, -10.0f, 0.0f);
    splat.assign(64, glm::vec4(3.0f * u_old, 3.0f));
    velocity.assign(64, glm::vec4(u_new, 1.0f));
  }
};

ParticleSnapshot one_particle(glm::vec3 x, glm::vec3 v) { return {{glm::vec4(x, 1.0f)}, {glm::vec4(v, 0.0f)}}; }

}  // namespace

TEST_CASE("the energy budget splits a step's change of energy into its terms", "[oscillation]") {
  const double m = 2.0, dt = 0.01, g = 10.0;
  SECTION("falling from rest: gravity's work, and no advection term when the step moves by the mean velocity") {
    UniformGrid grid(glm::vec3(0.0f), glm::vec3(0.0f, -float(g * dt), 0.0f));
    const glm::vec3 x0(0.4f, 0.4f, 0.0f), v1(0.0f, -float(g * dt), 0.0f);
    const EnergyBudget b = step_energy_budget(grid.setup, 0.0, one_particle(x0, glm::vec3(0.0f)),
                                              one_particle(x0 + float(0.5 * dt) * v1, v1), grid.splat, grid.velocity);
    CHECK(b.kinetic == Approx(0.5 * m * g * g * dt * dt).epsilon(1e-4));
    CHECK(b.gravity_work == Approx(b.kinetic).epsilon(1e-4));
    CHECK(b.potential == Approx(-b.kinetic).epsilon(1e-4));
    CHECK(b.advection() == Approx(0.0).margin(1e-6));  // of 0.01 J, in float positions
    CHECK(b.pressure_and_grid_walls == Approx(0.0).margin(1e-8));
    CHECK(b.pic == 0.0);
    CHECK(b.particle_walls == Approx(0.0).margin(1e-8));
  }
  SECTION("moved by the end velocity instead: the advection loses half of it (it fell further than it sped up)") {
    UniformGrid grid(glm::vec3(0.0f), glm::vec3(0.0f, -float(g * dt), 0.0f));
    const glm::vec3 x0(0.4f, 0.4f, 0.0f), v1(0.0f, -float(g * dt), 0.0f);
    const EnergyBudget b = step_energy_budget(grid.setup, 0.0, one_particle(x0, glm::vec3(0.0f)),
                                              one_particle(x0 + float(dt) * v1, v1), grid.splat, grid.velocity);
    CHECK(b.advection() == Approx(-0.5 * m * g * g * dt * dt).epsilon(1e-3));
  }
  SECTION("the PIC share pulls a particle towards the grid, a wall stops it") {
    UniformGrid grid(glm::vec3(0.0f), glm::vec3(0.0f));
    grid.setup.gravity = glm::vec3(0.0f);
    const glm::vec3 x0(0.4f, 0.4f, 0.0f), v0(1.0f, 0.0f, 0.0f);
    EnergyBudget b = step_energy_budget(grid.setup, 0.5, one_particle(x0, v0), one_particle(x0, 0.5f * v0),
                                        grid.splat, grid.velocity);
    CHECK(b.pic == Approx(0.5 * m * (0.25 - 1.0)));
    CHECK(b.kinetic == Approx(b.pic));
    CHECK(b.particle_walls == Approx(0.0).margin(1e-12));
    b = step_energy_budget(grid.setup, 0.5, one_particle(x0, v0), one_particle(x0, glm::vec3(0.0f)), grid.splat,
                           grid.velocity);
    CHECK(b.particle_walls == Approx(-0.5 * m * 0.25));
  }
}

TEST_CASE("under the affine transfer the energy budget reads the grids by the particle pass's fit", "[oscillation]") {
  // u' linear in y over the bottom five rows of cells, the rows above empty: by the fit a linear
  // field comes back exactly at a particle under the surface, where the bilinear read over the
  // cells holding liquid does not (it averages towards the cells below).
  UniformGrid grid(glm::vec3(0.0f), glm::vec3(0.0f));
  grid.setup.gravity = glm::vec3(0.0f);
  grid.setup.kernel_radius_cells = 3.0f;
  const auto u_at = [](float y) { return glm::vec3(1.0f + 2.0f * y, 0.0f, 0.0f); };
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const size_t cell = size_t(y) * 8 + size_t(x);
      const bool liquid = y < 5;
      grid.velocity[cell] = liquid ? glm::vec4(u_at((float(y) + 0.5f) * 0.1f), 1.0f) : glm::vec4(0.0f);
      grid.splat[cell] = liquid ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(0.0f);
    }
  const glm::vec3 x0(0.4f, 0.47f, 0.0f);  // between the top row of liquid (centres at 0.45) and the empty one
  const double expected = 0.5 * 2.0 * std::pow(double(u_at(x0.y).x), 2.0);  // v' = u'(x0) from rest, PIC 1
  const EnergyBudget fit = step_energy_budget(grid.setup, 1.0, one_particle(x0, glm::vec3(0.0f)),
                                              one_particle(x0, u_at(x0.y)), grid.splat, grid.velocity, Transfer::Affine);
  CHECK(fit.pressure_and_grid_walls == Approx(expected).epsilon(1e-4));
  CHECK(fit.particle_walls == Approx(0.0).margin(1e-4));
  const EnergyBudget bilinear = step_energy_budget(grid.setup, 1.0, one_particle(x0, glm::vec3(0.0f)),
                                                   one_particle(x0, u_at(x0.y)), grid.splat, grid.velocity);
  CHECK(bilinear.pressure_and_grid_walls < 0.99 * expected);  // the top row's 1.9 m/s, not 1.94
}
