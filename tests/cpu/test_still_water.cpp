// Still water's measures with no GPU: the surface from the particles and the density profile
// against hydrostatics.
#include "liquid/analysis/still_water.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace liquid;

TEST_CASE("the surface level is the mean top particle of the middle columns plus half a spacing", "[still]") {
  const double length = 0.5, s = 0.005;
  ParticleSnapshot particles;
  // Columns 40 mm deep at the left, 50 mm from the middle on; the outer tenths stand taller and
  // are left out.
  for (double x = 0.5 * s; x < length; x += s) {
    const double top = x < 0.05 || x > 0.45 ? 0.09 : x < 0.25 ? 0.04 : 0.05;
    for (double y = 0.5 * s; y < top; y += s) particles.positions.emplace_back(float(x), float(y), 0.0f, 1.0f);
  }
  // Half of the middle columns are 40 mm (top particle at 37.5 mm), half 50 mm (47.5 mm).
  CHECK(particle_surface_level(particles, length, s) == Approx(0.5 * (0.0375 + 0.0475) + 0.5 * s).epsilon(0.01));
  CHECK(std::isnan(particle_surface_level(ParticleSnapshot{}, length, s)));
}

TEST_CASE("the surface level's columns tile the middle of the tank with no sliver at its edges", "[still]") {
  // Particle columns 4.5 mm apart, 40 mm deep, but the one at x = 51.5 mm, just inside the middle
  // 80 % (from 50 mm), only 10 mm deep (its top layer drifted aside). Columns of the tank's own
  // width (0.5 m / 55) would cut a 4.5 mm sliver at 50 mm holding that column alone; columns
  // tiling the middle pair it with the next one, whose top stands at the level.
  const double length = 0.5, s = 0.0045;
  ParticleSnapshot particles;
  for (double x = 0.002; x < length; x += s) {
    const double top = std::abs(x - 0.0515) < 1e-6 ? 0.01 : 0.04;
    for (double y = 0.5 * s; y < top; y += s) particles.positions.emplace_back(float(x), float(y), 0.0f, 1.0f);
  }
  double highest = 0.0;
  for (const glm::vec4& p : particles.positions) highest = std::max(highest, double(p.y));
  CHECK(particle_surface_level(particles, length, s) == Approx(highest + 0.5 * s).epsilon(1e-6));
}

TEST_CASE("the density profile's slope is read against hydrostatics", "[still]") {
  SimulationSetup setup;
  setup.dimension = 2;
  setup.grid_cells = glm::ivec3(20, 40, 1);
  setup.cell_size = 0.01f;
  setup.kernel_radius_cells = 3.0f;
  setup.gravity = glm::vec3(0.0f, -9.81f, 0.0f);
  setup.stiffness = 10.0f;
  setup.gamma = 5.0f;
  // A surface at 0.3 m over a ratio rising at 0.15 / m of depth (and nonsense beyond the fitted rows:
  // in the kernel's reach of the floor and the surface, and outside the middle columns).
  const double surface = 0.3, rise = 0.15;
  std::vector<float> ratio(20 * 40, 0.0f);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 20; ++x) {
      const double centre = (y + 0.5) * 0.01;
      const bool fitted = centre > 0.03 && centre < surface - 0.03 && x >= 2 && x < 18;
      ratio[size_t(y) * 20 + size_t(x)] = fitted ? float(1.0 + rise * (surface - centre)) : 7.0f;
    }
  const DensityProfile p = density_profile(ratio, setup, surface);
  CHECK(p.rows == 24);  // centres 0.035 to 0.265
  CHECK(p.slope == Approx(rise).epsilon(1e-3));
  // g / (k gamma r^(gamma - 1)) at the mean ratio, 1 + 0.15 * 0.15.
  CHECK(p.hydrostatic == Approx(9.81 / (50.0 * std::pow(1.0225, 4.0))).epsilon(1e-3));
  CHECK(density_profile({}, setup, surface).rows == 0);
}
