// The chapter's splat kernel on the CPU (section 3), for the setup's calibrations.
#pragma once

namespace liquid {

// w(d, r) = (1 - d^2/r^2)^3 for d < r, from the squared distance.
inline double kernel_weight(double distance_squared, double radius) {
  const double q = 1.0 - distance_squared / (radius * radius);
  return q > 0.0 ? q * q * q : 0.0;
}

// Past this many lattice spacings per kernel radius a lattice sum of w equals the kernel's integral
// to far better than float precision, so the setup's calibrations take the integral instead.
constexpr double k_max_summed_lattice_ratio = 16.0;

// Sub-cell offsets per axis a lattice is averaged over where the calibrations sum it (the automatic
// rest density, the walls' coverage table).
constexpr int k_lattice_offsets_per_axis = 4;

}  // namespace liquid
