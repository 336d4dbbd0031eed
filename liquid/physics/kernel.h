// The splat kernels on the CPU (section 3), for the setup's calibrations: the chapter's radial
// kernel, and the separable splat's tensor-product kernel (docs/physics.md, "The separable splat").
#pragma once

#include "liquid/scene.h"

#include <cmath>

namespace liquid {

// w(d, r) = (1 - d^2/r^2)^3 for d < r, from the squared distance.
inline double kernel_weight(double distance_squared, double radius) {
  const double q = 1.0 - distance_squared / (radius * radius);
  return q > 0.0 ? q * q * q : 0.0;
}

// The separable splat spreads a particle's deposit by one pass per axis with the taps
// b_j = w(j, r), |j| <= separable_reach(r) (shaders/liquid/solver/separable_blur.frag).
inline int separable_reach(double radius) { return int(std::ceil(radius)) - 1; }

// Its kernel along one axis: the bilinear deposit (weights 1 - |t - j| on the two cells around the
// particle) followed by the taps is the taps' piecewise-linear interpolant at the offset t (cells).
inline double separable_profile(double t, double radius) {
  t = std::abs(t);
  const double j = std::floor(t);
  if (j >= separable_reach(radius) + 1) return 0.0;
  const double f = t - j;
  return (1.0 - f) * kernel_weight(j * j, radius) + f * kernel_weight((j + 1) * (j + 1), radius);
}

// The kernel a particle at offset (dx, dy, dz) cells from a cell centre adds there, by the scene's
// splat: radial (the chapter's) or the product of the axes' profiles (dz = 0 in 2D).
inline double splat_kernel_weight(SplatMode mode, double dx, double dy, double dz, double radius) {
  if (mode == SplatMode::PointSprite) return kernel_weight(dx * dx + dy * dy + dz * dz, radius);
  return separable_profile(dx, radius) * separable_profile(dy, radius) * separable_profile(dz, radius);
}

// How far the kernel reaches from a particle, cells: r for the radial kernel, reach + 1 for the
// separable one (its profile vanishes at the first tap past the reach).
inline double splat_kernel_support(SplatMode mode, double radius) {
  return mode == SplatMode::PointSprite ? radius : double(separable_reach(radius) + 1);
}

// Past this many lattice spacings per kernel radius a lattice sum of w equals the kernel's integral
// to far better than float precision, so the setup's calibrations take the integral instead.
constexpr double k_max_summed_lattice_ratio = 16.0;

// Sub-cell offsets per axis a lattice is averaged over where the calibrations sum it (the automatic
// rest density, the walls' coverage table).
constexpr int k_lattice_offsets_per_axis = 4;

}  // namespace liquid
