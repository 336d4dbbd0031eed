// How numbers appear in messages, written once for the scene checks and the setup's own: 0.6, 12,
// 1000000, 1e-06.
#pragma once

#include <string>
#include <string_view>

namespace liquid {

std::string format_number(double value);

// Text from the user (a key, a path) as a message shows it on one line: control characters
// escaped (\n, \t, \x01) and anything past `max_bytes` cut, saying how long it was.
std::string printable(std::string_view text, size_t max_bytes = 80);

}  // namespace liquid
