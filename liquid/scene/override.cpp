#include "liquid/scene/override.h"

#include "liquid/scene/format.h"
#include "liquid/scene/json_nesting.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace liquid {
namespace {

using Json = nlohmann::json;

// "fluid_blocks[0].max" -> {"fluid_blocks", "0", "max"}.
std::vector<std::string> path_parts(const std::string& path) {
  std::string dotted = path;
  for (char& c : dotted)
    if (c == '[') c = '.';
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(dotted);
  while (std::getline(in, part, '.')) {
    if (!part.empty() && part.back() == ']') part.pop_back();
    if (part.empty() || part.find(']') != std::string::npos) return {};
    parts.push_back(part);
  }
  if (!dotted.empty() && dotted.back() == '.') return {};
  return parts;
}

// Why a path with no parts (empty, "a..b", "a.") is refused, the same from parse_scene_override()
// (a bad flag) and apply() (an override built in code).
std::string not_a_field_path(const std::string& path) {
  return "--set " + printable(path) + ": not a field path (use name, camera.position, fluid_blocks.0.max)";
}

bool is_index(const std::string& part) {
  return !part.empty() && part.find_first_not_of("0123456789") == std::string::npos && part.size() < 10;
}

void apply(Json& doc, const SceneOverride& o) {
  const std::string where = "--set " + printable(o.path);
  const std::vector<std::string> parts = path_parts(o.path);
  if (parts.empty()) throw SceneError(not_a_field_path(o.path));
  // The scene file's limits, checked before the value is parsed or the document printed again.
  if (o.value.size() > k_max_scene_bytes)
    throw SceneError(where + ": the value is " + format_number(double(o.value.size())) + " bytes, larger than the " +
                     format_number(double(k_max_scene_bytes >> 20)) + " MiB a scene may be");
  if (parts.size() + size_t(json_nesting_depth(o.value)) > size_t(k_max_scene_nesting))
    throw SceneError(where + ": the path and its value nest deeper than the " + std::to_string(k_max_scene_nesting) +
                     " levels a scene may");
  Json* node = &doc;
  std::string walked;
  for (const std::string& part : parts) {
    if (node->is_array()) {
      if (!is_index(part))
        throw SceneError(where + ": " + printable(walked) + " is a list; expected an index, got '" + printable(part) + "'");
      const size_t index = std::stoul(part);
      if (index >= node->size())
        throw SceneError(where + ": " + printable(walked) + " has " + std::to_string(node->size()) + " element(s), no [" +
                         part + "]");
      node = &(*node)[index];
      walked += "[" + part + "]";
    } else if (node->is_object()) {
      node = &(*node)[part];  // a new key is added; the reader refuses it if it is unknown
      walked += (walked.empty() ? "" : ".") + part;
    } else if (node->is_null()) {
      if (is_index(part))  // a list the scene does not have: no element to set
        throw SceneError(where + ": the scene has no " + printable(walked) + ", so no [" + part + "]");
      *node = Json::object();  // a missing parent object (camera.position without a camera)
      node = &(*node)[part];
      walked += (walked.empty() ? "" : ".") + part;
    } else {
      throw SceneError(where + ": " + printable(walked) + " is a " + node->type_name() + ", it has no field '" +
                       printable(part) + "'");
    }
  }
  Json value = Json::parse(o.value, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) {
    // Not JSON, so a string; but a number too large for a double ("1e999") is a number.
    char* end = nullptr;
    const double number = std::strtod(o.value.c_str(), &end);
    if (!o.value.empty() && end == o.value.c_str() + o.value.size() && !std::isfinite(number))
      throw SceneError(where + ": " + printable(o.value) + " is not a finite number");
    value = Json(o.value);
  }
  *node = std::move(value);
}

}  // namespace

SceneOverride parse_scene_override(const std::string& text) {
  const size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw ArgumentError("--set " + printable(text) + ": expected key=value (e.g. --set stiffness=20)");
  // A path that cannot name a field is a bad flag too, refused before any scene is read.
  if (path_parts(text.substr(0, equals)).empty()) throw ArgumentError(not_a_field_path(text.substr(0, equals)));
  return {text.substr(0, equals), text.substr(equals + 1)};
}

std::string scene_document(const std::filesystem::path& path, const std::vector<SceneOverride>& overrides) {
  load_scene(path);  // the file on its own: its errors name the file and field
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  if (overrides.empty()) return text.str();
  Json doc = Json::parse(text.str());  // cannot fail: load_scene() parsed the same text
  // The default name comes from the file name, which the document is read without.
  if (doc.is_object() && !doc.contains("name")) doc["name"] = path.stem().string();
  for (const SceneOverride& o : overrides) apply(doc, o);
  return doc.dump(2);
}

}  // namespace liquid
