// How numbers appear in messages, written once for the scene checks and the setup's own: 0.6, 12,
// 1000000, 1e-06.
#pragma once

#include <string>

namespace liquid {

std::string format_number(double value);

}  // namespace liquid
