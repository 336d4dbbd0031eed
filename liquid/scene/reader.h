// The typed, path-aware JSON reader the scene loader is built on: every check names the file and
// the field ("scene.json: fluid_blocks[1].min: must be inside the domain ..."). Internal to
// liquid/scene/.
#pragma once

#include "liquid/scene.h"
#include "liquid/scene/format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <sstream>
#include <string>

namespace liquid::scene_reader {

using Json = nlohmann::json;

constexpr double k_max_length = 100.0;  // m, radii, half extents, hill sizes: the default vector bound

inline std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? printable(key) : path + "." + printable(key);
}

inline std::string element(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

// Walks one document: knows the source name (prefix of every message) and, once read, the
// dimension and domain that later fields are checked against.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  // The scene's file (or parse_scene's source name): files it names are relative to its folder.
  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw SceneError(source_ + ": " + path + ": " + reason);
  }

  // Requires `value` to be an object whose keys are all in `allowed`.
  void check_keys(const Json& value, const std::string& path, std::initializer_list<const char*> allowed) const {
    check_keys(value, path, std::span<const char* const>(allowed.begin(), allowed.size()));
  }
  void check_keys(const Json& value, const std::string& path, std::span<const char* const> allowed) const {
    if (!value.is_object()) fail(path, std::string("must be an object, got ") + value.type_name());
    for (const auto& item : value.items()) {
      const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* k) { return item.key() == k; });
      if (!known) fail(child(path, item.key()), "unknown key");
    }
  }

  // The member `key` of an object, or nullptr when absent.
  static const Json* find(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const Json& require(const Json& object, const std::string& path, const char* key) const {
    const Json* value = find(object, key);
    if (!value) fail(child(path, key), "missing required key");
    return *value;
  }

  // A finite number that also fits a float (the solver's precision).
  double number(const Json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, std::string("must be a number, got ") + value.type_name());
    const double x = value.get<double>();
    if (!std::isfinite(x) || std::abs(x) > double(FLT_MAX)) fail(path, "must be a finite number");
    return x;
  }

  // A number in [lo, hi]; `lo_open` / `hi_open` exclude the bound.
  double number_in(const Json& value, const std::string& path, double lo, double hi, bool lo_open = false,
                   bool hi_open = false) const {
    const double x = number(value, path);
    if ((lo_open ? x <= lo : x < lo) || (hi_open ? x >= hi : x > hi))
      fail(path, "must be in " + std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
                     (hi_open ? ")" : "]") + ", got " + format_number(x));
    return x;
  }

  // An integer in [lo, hi]; an integral float such as 64.0 is accepted.
  int integer_in(const Json& value, const std::string& path, int lo, int hi) const {
    if (!value.is_number()) fail(path, std::string("must be an integer, got ") + value.type_name());
    const double x = value.get<double>();
    if (!std::isfinite(x) || x != std::floor(x)) fail(path, "must be an integer, got " + format_number(x));
    if (x < lo || x > hi)
      fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + format_number(x));
    return int(x);
  }

  std::string string(const Json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, std::string("must be a string, got ") + value.type_name());
    return value.get<std::string>();
  }

  // One of a fixed set of strings; returns its index in `choices`.
  size_t choice(const Json& value, const std::string& path, std::initializer_list<const char*> choices) const {
    return choice(value, path, std::span<const char* const>(choices.begin(), choices.size()));
  }
  size_t choice(const Json& value, const std::string& path, std::span<const char* const> choices) const {
    const std::string text = string(value, path);
    std::string list;
    size_t index = 0;
    for (const char* option : choices) {
      if (text == option) return index;
      list += (index++ ? ", \"" : "\"") + std::string(option) + "\"";
    }
    fail(path, "must be one of " + list + ", got \"" + text + "\"");
  }

  // A vector of exactly `length` finite numbers, each with |x| <= bound; z = 0 when length is 2.
  glm::vec3 vector(const Json& value, const std::string& path, int length, double bound = k_max_length) const {
    if (!value.is_array()) fail(path, std::string("must be an array of numbers, got ") + value.type_name());
    if (int(value.size()) != length)
      fail(path, "must have " + std::to_string(length) + " components, got " + std::to_string(value.size()));
    glm::vec3 v(0.0f);
    for (int i = 0; i < length; ++i) v[i] = float(number_in(value[size_t(i)], element(path, size_t(i)), -bound, bound));
    return v;
  }

  // A vector of the scene's dimension.
  glm::vec3 scene_vector(const Json& value, const std::string& path, double bound = k_max_length) const {
    return vector(value, path, dimension_, bound);
  }

  // A scene vector that must lie in the closed domain box.
  glm::vec3 point_in_domain(const Json& value, const std::string& path) const {
    const glm::vec3 p = scene_vector(value, path);
    for (int a = 0; a < dimension_; ++a)
      if (p[a] < 0.0f || p[a] > domain_[a]) fail(path, "must be inside the domain " + describe_domain());
    return p;
  }

  // "[0, 1] x [0, 0.6]".
  std::string describe_domain() const {
    std::string text;
    for (int a = 0; a < dimension_; ++a) text += (a ? " x [0, " : "[0, ") + format_number(domain_[a]) + "]";
    return text;
  }

  void set_space(int dimension, glm::vec3 domain) {
    dimension_ = dimension;
    domain_ = domain;
  }
  int dimension() const { return dimension_; }

 private:
  std::string source_;
  int dimension_ = 2;
  glm::vec3 domain_{0.0f};
};

// Reads the scene from a parsed document (liquid/scene/scene.cpp); throws SceneError naming the field.
Scene read_scene(const Json& doc, const std::string& source_name);

}  // namespace liquid::scene_reader
