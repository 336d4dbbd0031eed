// A download's bytes as `count` texels of T (RGBA32F as glm::vec4), for the Simulation's read-backs
// and checkpoints.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

namespace liquid {

template <class T>
std::vector<T> texels_as(const std::vector<std::byte>& bytes, size_t count) {
  std::vector<T> out(count);
  // No particles yet (an emitter's first steps): both vectors may be empty, their data() null,
  // which memcpy must not be given even for no bytes.
  if (const size_t size = std::min(bytes.size(), count * sizeof(T)); size > 0) std::memcpy(out.data(), bytes.data(), size);
  return out;
}

}  // namespace liquid
