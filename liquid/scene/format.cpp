#include "liquid/scene/format.h"

#include <cmath>
#include <cstdint>
#include <sstream>

namespace liquid {

std::string format_number(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) return std::to_string(std::int64_t(value));
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace liquid
