// The scene's plain number keys, a row each: key, member, range, and whether shallow water refuses
// it. A new number of the scene is its member in include/liquid/scene.h and one row in scene.cpp's
// table: the reader checks it, the known-key list includes it, and tests/cpu/test_scene.cpp walks
// the table (each key's range refused on both sides, a value inside read back, the README's row).
// Internal to liquid/scene/ and the tests.
#pragma once

#include "liquid/scene.h"

#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace liquid::scene_reader {

using NumberMember =
    std::variant<float Scene::*, std::optional<float> Scene::*, int Scene::*, std::optional<int> Scene::*>;

struct NumberKey {
  const char* key;
  NumberMember member;
  double lo;
  double hi;
  bool lo_open = false;                  // (lo, hi] instead of [lo, hi]
  const char* shallow_refusal = nullptr;  // set: refused in shallow_water mode with this reason
};

// Every row, in the order the reader reads them.
std::span<const NumberKey> number_keys();

// Every key a scene's top level may have: the rows' and those read by code of their own.
std::vector<const char*> top_level_keys();

}  // namespace liquid::scene_reader
