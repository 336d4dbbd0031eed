// Scene fields set from outside the file (the capture tool's --set key=value): applied to the
// file's JSON document before it is read, so an overridden value is checked exactly like one
// written in the file, with the same messages.
#pragma once

#include "liquid/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace liquid {

struct SceneOverride {
  std::string path;   // dotted, into nested fields and arrays: "stiffness", "camera.position",
                      // "fluid_blocks.0.max" (also "fluid_blocks[0].max")
  std::string value;  // JSON ("12", "[0.1, 0.2]", "true"); text that is not JSON is a string
};

// Splits "key=value"; throws ArgumentError naming the text when there is no key.
SceneOverride parse_scene_override(const std::string& key_equals_value);

// The scene document after the overrides, as JSON text: the file is read and checked as it is
// first (load_scene(), so its own errors keep their messages), then each override replaces or
// adds its field (a document without "name" gets the file's stem, its default). Throws SceneError naming the override when its path cannot be followed (an
// array index past the end, a field inside a number).
std::string scene_document(const std::filesystem::path& path, const std::vector<SceneOverride>& overrides);

}  // namespace liquid
