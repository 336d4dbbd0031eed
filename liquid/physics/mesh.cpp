#include "liquid/physics/mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {

// Closest distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
float triangle_distance(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(ap);
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return glm::length(bp);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(ap - ab * (d1 / (d1 - d3)));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return glm::length(cp);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(ap - ac * (d2 / (d2 - d6)));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return glm::length(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const float denom = 1.0f / (va + vb + vc);
  return glm::length(ap - ab * (vb * denom) - ac * (vc * denom));
}

}  // namespace

glm::mat4 mesh_to_world(const TriangleMesh& mesh, glm::vec3 center) { return mesh_to_world(mesh, center, mesh.rotation); }

glm::mat4 mesh_to_world(const TriangleMesh& mesh, glm::vec3 center, glm::quat rotation) {
  return glm::translate(glm::mat4(1.0f), center) * glm::mat4_cast(rotation) *
         glm::scale(glm::mat4(1.0f), glm::vec3(mesh.scale));
}

float longest_edge(const TriangleMesh& mesh) {
  float longest = 0.0f;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, glm::distance(mesh.vertices[mesh.indices[t + k]],
                                                mesh.vertices[mesh.indices[t + (k + 1) % 3]]));
  return longest;
}

PlacedMesh::PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, float reach)
    : PlacedMesh(mesh, center, mesh.rotation, reach) {}

PlacedMesh::PlacedMesh(const TriangleMesh& mesh, glm::vec3 center, glm::quat rotation, float reach) : reach_(reach) {
  const glm::mat4 m = mesh_to_world(mesh, center, rotation);
  lo_ = glm::vec3(INFINITY);
  hi_ = glm::vec3(-INFINITY);
  for (uint32_t i : mesh.indices) {
    corners_.push_back(glm::vec3(m * glm::vec4(mesh.vertices[i], 1.0f)));
    lo_ = glm::min(lo_, corners_.back());
    hi_ = glm::max(hi_, corners_.back());
  }
  // inside()'s ray moved off the point by a sliver at an odd angle, so one passing exactly through
  // an edge or a vertex (a lattice point on the mesh's axis) meets each surface once, not twice or
  // never: a sliver of the triangles' own extent, whatever the reach.
  ray_offset_ = glm::vec3(0.7316f, 0.4157f, 0.0f) * (1e-6f * std::max(hi_.x - lo_.x, hi_.y - lo_.y));
  lo_ -= reach;
  hi_ += reach;
  build_hierarchy();
}

// Top-down, split at the median centroid along the box's longest axis, leaves of a few triangles:
// n log n to build, balanced whatever the mesh.
void PlacedMesh::build_hierarchy() {
  constexpr uint32_t k_leaf_triangles = 4;
  const uint32_t triangles = uint32_t(corners_.size() / 3);
  order_.resize(triangles);
  std::vector<glm::vec3> centroid(triangles);
  for (uint32_t t = 0; t < triangles; ++t) {
    order_[t] = t;
    centroid[t] = (corners_[3 * t] + corners_[3 * t + 1] + corners_[3 * t + 2]) / 3.0f;
  }
  nodes_.clear();
  nodes_.reserve(2 * size_t(triangles) + 1);  // a binary tree of at most one leaf per triangle
  struct Range {
    uint32_t node, begin, end;
  };
  std::vector<Range> pending;
  nodes_.push_back({});
  pending.push_back({0, 0, triangles});
  while (!pending.empty()) {
    const Range r = pending.back();
    pending.pop_back();
    Node node{glm::vec3(INFINITY), glm::vec3(-INFINITY), 0, 0};
    for (uint32_t i = r.begin; i < r.end; ++i)
      for (int k = 0; k < 3; ++k) {
        node.lo = glm::min(node.lo, corners_[3 * order_[i] + k]);
        node.hi = glm::max(node.hi, corners_[3 * order_[i] + k]);
      }
    if (r.end - r.begin <= k_leaf_triangles) {
      node.first = r.begin;
      node.count = r.end - r.begin;
      nodes_[r.node] = node;
      continue;
    }
    const glm::vec3 extent = node.hi - node.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const uint32_t middle = r.begin + (r.end - r.begin) / 2;
    std::nth_element(order_.begin() + r.begin, order_.begin() + middle, order_.begin() + r.end,
                     [&](uint32_t a, uint32_t b) { return centroid[a][axis] < centroid[b][axis]; });
    node.first = uint32_t(nodes_.size());
    nodes_[r.node] = node;
    nodes_.push_back({});
    nodes_.push_back({});
    pending.push_back({node.first, r.begin, middle});
    pending.push_back({node.first + 1, middle, r.end});
  }
}

// The distance to the nearest triangle if it is under `within`, else `within`: boxes farther than
// the nearest so far are skipped, the nearer child visited first.
float PlacedMesh::nearest_surface(glm::vec3 p, float within) const {
  if (nodes_.empty()) return within;
  const auto box_distance_squared = [&](const Node& n) {
    const glm::vec3 outside = glm::max(glm::max(n.lo - p, p - n.hi), glm::vec3(0.0f));
    return glm::dot(outside, outside);
  };
  float best = within;
  uint32_t stack[64];
  int depth = 0;
  stack[depth++] = 0;
  while (depth > 0) {
    const Node& n = nodes_[stack[--depth]];
    if (box_distance_squared(n) >= best * best) continue;
    if (n.count > 0) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i) {
        const uint32_t t = order_[i];
        best = std::min(best, triangle_distance(p, corners_[3 * t], corners_[3 * t + 1], corners_[3 * t + 2]));
      }
      continue;
    }
    const bool left_first = box_distance_squared(nodes_[n.first]) <= box_distance_squared(nodes_[n.first + 1]);
    // A balanced tree of at most 2^25 triangles is about 24 deep: the stack never holds 64.
    stack[depth++] = left_first ? n.first + 1 : n.first;
    stack[depth++] = left_first ? n.first : n.first + 1;
  }
  return best;
}


// The winding number along the ray from p toward +z: each triangle above p whose projection covers
// p adds the sign of its normal's z (+1 leaving the solid, -1 entering). Only the boxes the ray
// passes through are opened.
int PlacedMesh::winding_above(glm::vec3 p) const {
  if (nodes_.empty()) return 0;
  int winding = 0;
  uint32_t stack[64];  // one pending sibling per level: a balanced tree is about 24 deep
  int depth = 0;
  stack[depth++] = 0;
  while (depth > 0) {
    const Node& n = nodes_[stack[--depth]];
    if (p.x < n.lo.x || p.x > n.hi.x || p.y < n.lo.y || p.y > n.hi.y || p.z >= n.hi.z) continue;
    if (n.count == 0) {
      stack[depth++] = n.first;
      stack[depth++] = n.first + 1;
      continue;
    }
    for (uint32_t i = n.first; i < n.first + n.count; ++i) {
      const uint32_t t = order_[i];
      const glm::vec3 a = corners_[3 * t], c1 = corners_[3 * t + 1], c2 = corners_[3 * t + 2];
      const float area = (c1.x - a.x) * (c2.y - a.y) - (c2.x - a.x) * (c1.y - a.y);
      if (area == 0.0f) continue;
      const float w1 = ((c2.x - p.x) * (a.y - p.y) - (a.x - p.x) * (c2.y - p.y)) / area;
      const float w2 = ((a.x - p.x) * (c1.y - p.y) - (c1.x - p.x) * (a.y - p.y)) / area;
      const float w0 = 1.0f - w1 - w2;
      if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
      if (w0 * a.z + w1 * c1.z + w2 * c2.z <= p.z) continue;
      winding += area > 0.0f ? 1 : -1;
    }
  }
  return winding;
}

bool PlacedMesh::inside(glm::vec3 p) const {
  if (glm::any(glm::lessThan(p, lo_)) || glm::any(glm::greaterThan(p, hi_))) return false;
  return winding_above(p + ray_offset_) != 0;
}

float PlacedMesh::distance(glm::vec3 p) const {
  const float nearest = nearest_surface(p, reach_);
  return inside(p) ? -nearest : nearest;
}

}  // namespace liquid
