// The travelling pulse with no GPU: its hump's modes by the cosine series, the scene that holds it,
// and the modes projected from its particles.
#include "liquid/analysis/travelling_wave.h"
#include "liquid/physics/setup.h"
#include "tests/support/scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace liquid;

TEST_CASE("the pulse's modes are its hump's cosine series", "[oscillation]") {
  const TravellingPulse pulse = travelling_pulse(2, 128);
  CHECK(pulse.height == Approx(0.01));  // h / 10
  CHECK(pulse.half_width == Approx(0.05));
  // The hump is ten widths from the far wall: its series is the Gaussian's transform,
  // a_n = (2 / L) A sigma sqrt(pi / 2) exp(-(k_n sigma)^2 / 2).
  for (int n = 1; n <= 4; ++n) {
    const double k = n * std::numbers::pi / pulse.tank.length;
    const double expected = 2.0 / pulse.tank.length * pulse.height * pulse.half_width * std::sqrt(0.5 * std::numbers::pi) *
                            std::exp(-0.5 * k * k * pulse.half_width * pulse.half_width);
    CHECK(pulse_mode_amplitude(pulse, n) == Approx(expected).epsilon(1e-6));
  }
  // Modes 1 to 3 carry comparable shares, the third still 2/3 of the first.
  CHECK(pulse_mode_amplitude(pulse, 3) > 0.6 * pulse_mode_amplitude(pulse, 1));
}

TEST_CASE("the pulse's particles hold its hump on whole layers of still water", "[oscillation]") {
  const Scene physics = test_scenes::scene_of("rest_pool_2d.json");
  for (int dimension : {2, 3}) {
    INFO(dimension << "D");
    const TravellingPulse pulse = travelling_pulse(dimension, 128);
    const Scene scene = travelling_pulse_scene(physics, pulse);
    const double s = scene.particle_spacing, length = pulse.tank.length;
    // The far wall's columns stand at the still depth, a whole number of layers within half a layer of h.
    const double still = scene.fluid_blocks.back().max.y;
    CHECK(std::abs(still / s - std::round(still / s)) < 1e-4);
    CHECK(still == Approx(pulse.tank.depth).margin(0.5 * s));
    CHECK(scene.fluid_blocks.front().max.y - still == Approx(pulse.height).margin(0.5 * s));
    // Projected from the lattice the solver starts from, each mode within a twentieth of the
    // series's (in 3D spread over the width).
    const SimulationSetup setup = make_setup(scene, DeviceLimits{});
    ParticleSnapshot particles;
    particles.positions = setup.positions;
    // Each particle stands for s^2 of the section, in 3D its volume over the tank's width (which
    // the lattice fills with whole spacings: the spacing is snapped to it).
    const double area = particle_section(scene);
    CHECK(area == Approx(dimension == 2 ? s * s : s * s * s / pulse.tank.width).epsilon(1e-5));  // float domain
    if (dimension == 3) CHECK(std::abs(pulse.tank.width / s - std::round(pulse.tank.width / s)) < 1e-4);
    // The depth it settles to: the still layers and the hump's volume over L, times the share of L
    // the whole spacings along it fill (all of it in 2D; the columns spread over the rest).
    const double filled = std::floor(length / s + 1e-4) * s / length;
    if (dimension == 2) CHECK(filled == Approx(1.0));
    const double hump = pulse.height * pulse.half_width * std::sqrt(0.5 * std::numbers::pi) / length;
    CHECK(settled_depth(scene, particles.positions.size()) ==
          Approx(filled * (still + hump)).margin(0.1 * s));
    for (int n = 1; n <= 3; ++n) {
      INFO("mode " << n);
      CHECK(tank_mode_amplitude(particles, n, length, area) ==
            Approx(filled * pulse_mode_amplitude(pulse, n)).epsilon(0.05));
    }
    // Still water has no mode: the lattice's columns cancel.
    const Scene flat = tank_scene(physics, pulse.tank, [&](double) { return still; });
    const SimulationSetup flat_setup = make_setup(flat, DeviceLimits{});
    ParticleSnapshot flat_particles;
    flat_particles.positions = flat_setup.positions;
    CHECK(tank_mode_amplitude(flat_particles, 1, length, area) == Approx(0.0).margin(1e-6));
  }
}
