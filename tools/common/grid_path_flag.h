// The --3d-path flag the tools share: how 3D grids are stored and rendered into (geometry,
// vertex-layer or atlas; liquid/solver/grid_layout.h), overriding the device's choice and LIQUID_3D_PATH.
#pragma once

#include "liquid/types.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>

namespace tools {

// Refuses any other name: "--3d-path: 'gs' is not a 3D path (geometry, vertex-layer or atlas)".
inline CLI::Validator grid_path_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string { return liquid::find_grid_path(text) ? "" : liquid::not_a_grid_path(text); },
      liquid::grid_path_names("|", "|"), "GRID_PATH");
}

inline CLI::Option* add_grid_path_option(CLI::App& app, std::string& name) {
  return app.add_option("--3d-path", name,
                        "3D grids: " + liquid::grid_path_names(", ", " or ") + " (default: the device's best)")
      ->check(grid_path_check());
}

// The path a --3d-path value names; empty when the flag was not given (checked by the validator).
inline std::optional<liquid::GridPath> grid_path_from_flag(const std::string& name) {
  return name.empty() ? std::nullopt : liquid::find_grid_path(name);
}

// The node's log lines, on stdout.
inline std::function<void(const std::string&)> stdout_log() {
  return [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
}

}  // namespace tools
