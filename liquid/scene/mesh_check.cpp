#include "liquid/scene/mesh_check.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

namespace liquid {

void weld_positions(TriangleMesh& mesh) {
  const auto key = [](glm::vec3 v) { return std::make_tuple(v.x, v.y, v.z); };
  std::map<std::tuple<float, float, float>, uint32_t> index_of;
  std::vector<glm::vec3> vertices;
  std::vector<uint32_t> remap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    auto [it, added] = index_of.try_emplace(key(mesh.vertices[i]), uint32_t(vertices.size()));
    if (added) vertices.push_back(mesh.vertices[i]);
    remap[i] = it->second;
  }
  std::vector<uint32_t> indices;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) v[k] = mesh.indices[t + k] < remap.size() ? remap[mesh.indices[t + k]] : UINT32_MAX;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;  // collapsed to a line or a point
    indices.insert(indices.end(), v, v + 3);
  }
  mesh.vertices = std::move(vertices);
  mesh.indices = std::move(indices);
}

std::string mesh_problem(const TriangleMesh& mesh) {
  if (mesh.indices.size() % 3 != 0)
    return "the index count (" + std::to_string(mesh.indices.size()) + ") is not a multiple of 3";
  const size_t triangles = mesh.indices.size() / 3;
  if (triangles == 0) return "the mesh has no triangles";
  for (uint32_t i : mesh.indices)
    if (i >= mesh.vertices.size())
      return "index " + std::to_string(i) + " is past the " + std::to_string(mesh.vertices.size()) + " vertices";
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (uint32_t i : mesh.indices) {
    const glm::vec3 v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return "a vertex is not finite";
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const glm::vec3 extent = hi - lo;
  const float largest = std::max(extent.x, std::max(extent.y, extent.z));
  if (!(largest > 0.0f) || std::min(extent.x, std::min(extent.y, extent.z)) <= 1e-6f * largest)
    return "degenerate extent (" + std::to_string(extent.x) + " x " + std::to_string(extent.y) + " x " +
           std::to_string(extent.z) + "): the mesh encloses no volume";
  // Each directed edge once, and its reverse once: every edge shared by two triangles that agree
  // on which side is outside. Sorted keys (from << 32 | to) visit the edges in a map's order at a
  // fraction of its cost.
  std::vector<uint64_t> directed;
  directed.reserve(3 * triangles);
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k)
      directed.push_back(uint64_t(mesh.indices[3 * t + k]) << 32 | mesh.indices[3 * t + (k + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  const auto occurrences = [&](uint64_t edge) {
    const auto [first, last] = std::equal_range(directed.begin(), directed.end(), edge);
    return last - first;
  };
  size_t bad = 0;
  uint64_t example = 0;
  for (size_t i = 0; i < directed.size();) {
    const uint64_t edge = directed[i];
    size_t end = i;
    while (end < directed.size() && directed[end] == edge) ++end;
    if (end - i != 1 || occurrences(edge << 32 | edge >> 32) != 1) {
      if (bad++ == 0) example = edge;
    }
    i = end;
  }
  if (bad > 0)
    return "the mesh is not closed: " + std::to_string(bad) +
           " edges are not shared by exactly two triangles of opposite orientation (e.g. vertices " +
           std::to_string(example >> 32) + "-" + std::to_string(example & 0xffffffffu) + ")";
  // Closed and consistent, it may still wind inward: the rasterizer's inside test and a body's mass
  // follow the winding, so it would make the liquid the obstacle and a body's volume negative.
  double six_volume = 0.0;
  for (size_t t = 0; t < triangles; ++t) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[3 * t]]), b(mesh.vertices[mesh.indices[3 * t + 1]]),
        c(mesh.vertices[mesh.indices[3 * t + 2]]);
    six_volume += glm::dot(a, glm::cross(b, c));
  }
  if (six_volume < 0.0)
    return "is inside out (its triangles wind clockwise seen from outside, so its volume is negative); "
           "reverse the order of each face's corners";
  return "";
}

}  // namespace liquid
