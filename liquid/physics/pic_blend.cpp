#include "liquid/physics/pic_blend.h"

#include <algorithm>
#include <cmath>

namespace liquid {

double pic_blend_for_step(double pic_ratio, double reference_step, double dt) {
  if (reference_step <= 0.0 || pic_ratio <= 0.0 || pic_ratio >= 1.0) return pic_ratio;
  return std::clamp(1.0 - std::pow(1.0 - pic_ratio, dt / reference_step), 0.0, 1.0);
}

}  // namespace liquid
