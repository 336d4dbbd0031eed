// Command-line conventions shared by the tools: a bad flag gives one line on stderr, like every
// other error of the tools, instead of CLI11's usage text; an error while running gives one line
// "<tool>: error: ..." and exit status 1.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

namespace tools {

// Parses the arguments; returns an exit code when the program should stop (after --help: 0, after
// a bad flag or value: 2, with "<tool>: error: ..." printed), or nothing to carry on.
inline std::optional<int> parse_arguments(CLI::App& app, int argc, char** argv, const char* tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::fprintf(stderr, "%s: error: %s\n", tool, error.what());
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
    std::fprintf(stderr, "%s: error: %s\n", tool, error.what());
    return 1;
  }
}

// Throws when the validation layer reported anything: a run with messages fails like any other
// error (one line, exit status 1).
inline void fail_on_validation_messages(uint32_t messages) {
  if (messages > 0) throw std::runtime_error(std::to_string(messages) + " validation message(s)");
}

}  // namespace tools
