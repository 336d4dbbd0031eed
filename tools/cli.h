// Command-line parsing shared by the tools: a bad flag gives one line on stderr, like every other
// error of the tools, instead of CLI11's usage text.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

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

}  // namespace tools
