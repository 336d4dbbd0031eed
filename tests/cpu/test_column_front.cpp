// The collapsing column's front against Martin and Moyce with no GPU: the comparison, and the
// release delay fitted to it (liquid::k_max_release_delay); the volume a settled pool is held to.
#include "liquid/analysis/validation.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace liquid;

namespace {

// The experiment's front, started `delay` early (T0 < 0: late), sampled every 0.01 from T = 0 to 3.4,
// with Z = 1 before it moves.
struct Front {
  std::vector<double> T, Z;
};
Front experiment_started_early(double delay) {
  const std::span<const ExperimentPoint> points = martin_moyce_front();
  Front f;
  for (double t = 0.0; t <= 3.4 + 1e-9; t += 0.01) {
    const double te = t + delay;  // the experiment's time this sample shows
    double z = 1.0;
    if (te >= points.back().T) {
      z = points.back().Z;
    } else {
      for (size_t i = 1; i < points.size(); ++i)
        if (te < points[i].T) {
          const double s = (te - points[i - 1].T) / (points[i].T - points[i - 1].T);
          z = te < points[0].T ? 1.0 : points[i - 1].Z + s * (points[i].Z - points[i - 1].Z);
          break;
        }
    }
    f.T.push_back(t);
    f.Z.push_back(z);
  }
  return f;
}

}  // namespace

TEST_CASE("the experiment's own front meets it with no release delay", "[validation]") {
  const Front f = experiment_started_early(0.0);
  const ReleasedFront r = compare_front_released(f.T, f.Z);
  CHECK(r.at_once.points == k_front_points);
  CHECK(r.at_once.mean < 1e-3);
  CHECK(r.delay == 0.0);
}

TEST_CASE("a front that starts a constant time early is met after that release delay, and no more", "[validation]") {
  // 0.2 early: found, and the error after it is that of the sampling alone.
  const Front early = experiment_started_early(0.2);
  const ReleasedFront r = compare_front_released(early.T, early.Z);
  CHECK(r.delay == Approx(0.2).margin(k_release_delay_step));
  CHECK(r.released.points == k_front_points);
  CHECK(r.released.mean < 0.005);
  CHECK(r.at_once.mean > 0.05);  // unshifted it is far off
  // 0.6 early: the delay stops at its bound, and the error past it stays.
  const Front far = experiment_started_early(0.6);
  const ReleasedFront capped = compare_front_released(far.T, far.Z);
  CHECK(capped.delay == Approx(k_max_release_delay).margin(1e-9));
  CHECK(capped.released.mean > 0.02);
  // A front that lags is not helped: no delay can bring it forward.
  const Front late = experiment_started_early(-0.2);
  const ReleasedFront behind = compare_front_released(late.T, late.Z);
  CHECK(behind.delay == 0.0);
  CHECK(behind.released.mean == behind.at_once.mean);
}

TEST_CASE("the particles' rest volume is their mass over the rest density") {
  SimulationSetup setup;
  setup.initial_particles = 1000;
  setup.particle_mass = 0.04f;  // kg (2D: per metre of depth)
  setup.rest_density = 1000.0f;
  CHECK(particles_rest_volume(setup) == Approx(0.04).epsilon(1e-6));
  setup.rest_density = 800.0f;  // a lattice read lighter: the same mass fills more
  CHECK(particles_rest_volume(setup) == Approx(0.05).epsilon(1e-6));
}
