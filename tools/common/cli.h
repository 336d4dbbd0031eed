// Command-line conventions shared by the tools: a bad flag gives one line on stderr, like every
// other error of the tools, instead of CLI11's usage text; an error while running gives one line
// "<tool>: error: ..." and exit status 1.
#pragma once

#include "liquid/scene/format.h"
#include "tools/common/keep_modules_loaded.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tools {

// Readable form of a bound or a value in messages: 1000000, 0.001, 1e+30.
inline std::string format_cli_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

// A check for a number flag (also each element of a list flag such as --camera-position x,y,z):
// the text must be a number, finite, in [lo, hi]. CLI11's own Range lets "nan" through (every
// comparison with NaN is false) and calls "abc" "not in range"; this says which is wrong:
//   --fps: must be a finite number, got 'nan'
inline CLI::Validator finite_range(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const char* begin = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);
        const char* end = text.data() + text.size();
        double value = 0.0;
        const auto [stop, error] = std::from_chars(begin, end, value);
        if (error == std::errc::invalid_argument || stop != end || begin == end)
          return "must be a number, got '" + text + "'";
        if (error == std::errc::result_out_of_range || !std::isfinite(value))
          return "must be a finite number, got '" + text + "'";
        if (value < lo || value > hi)
          return "must be in [" + format_cli_number(lo) + ", " + format_cli_number(hi) + "], got " + text;
        return {};
      },
      "NUMBER in [" + format_cli_number(lo) + ", " + format_cli_number(hi) + "]", "FINITE_RANGE");
}

// A check for an integer flag: the text must be a whole decimal integer in [lo, hi] ("1e3", "2.5"
// and "abc" are refused, naming the flag and the text).
inline CLI::Validator integer_range(std::int64_t lo, std::int64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const char* begin = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);
        const char* end = text.data() + text.size();
        std::int64_t value = 0;
        const auto [stop, error] = std::from_chars(begin, end, value);
        if (error == std::errc::invalid_argument || stop != end || begin == end)
          return "must be an integer, got '" + text + "'";
        if (error == std::errc::result_out_of_range || value < lo || value > hi)
          return "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + text;
        return {};
      },
      "INTEGER in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", "INTEGER_RANGE");
}

// A check for a flag naming a file or folder: an empty value ("--video ''", "--video=") is refused
// by name, "--video: needs a file name", instead of being taken for the flag not given.
inline CLI::Validator non_empty(const std::string& what) {
  return CLI::Validator([what](std::string& text) -> std::string { return text.empty() ? "needs " + what : ""; },
                        "NON_EMPTY", "NON_EMPTY");
}

// The most of one error message a tool prints: a message that echoes a huge argument back is cut.
inline constexpr size_t k_max_error_bytes = 4096;

// "<tool>: error: <what>" on one line: control characters in echoed user text (a newline in a key
// or a file name) are escaped and a message past k_max_error_bytes is cut, saying its length.
inline void print_error(const char* tool, const char* what) {
  std::fprintf(stderr, "%s: error: %s\n", tool, liquid::printable(what, k_max_error_bytes).c_str());
}

// Parses the arguments; returns an exit code when the program should stop (after --help: 0, after
// a bad flag or value: 2, with "<tool>: error: ..." printed), or nothing to carry on.
inline std::optional<int> parse_arguments(CLI::App& app, int argc, char** argv, const char* tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    print_error(tool, error.what());
    return 2;
  }
  return std::nullopt;
}

// The body of every tool's main(): parses the arguments (see parse_arguments), then runs `body`
// and returns its exit code; an exception from it becomes one line on stderr and exit status 1.
template <class Body>
int run_main(CLI::App& app, int argc, char** argv, const char* tool, Body&& body) {
  if (const std::optional<int> exit_code = parse_arguments(app, argc, argv, tool)) return *exit_code;
  try {
    return body();
  } catch (const std::exception& error) {
    print_error(tool, error.what());
    return 1;
  }
}

// Throws when the validation layer reported anything: a run with messages fails like any other
// error (one line, exit status 1).
inline void fail_on_validation_messages(uint32_t messages) {
  if (messages > 0) throw std::runtime_error(std::to_string(messages) + " validation message(s)");
}

}  // namespace tools
