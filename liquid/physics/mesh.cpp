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
  lo_ -= reach;
  hi_ += reach;
  const glm::vec3 extent = hi_ - lo_;
  buckets_ = glm::clamp(glm::ivec3(extent / std::max(reach, 1e-6f)), glm::ivec3(1), glm::ivec3(64));
  bucket_size_ = extent / glm::vec3(buckets_);
  bucket_triangles_.resize(size_t(buckets_.x) * buckets_.y * buckets_.z);
  column_triangles_.resize(size_t(buckets_.x) * buckets_.y);
  for (size_t t = 0; t < corners_.size() / 3; ++t) {
    glm::vec3 a = corners_[3 * t], b = corners_[3 * t + 1], c = corners_[3 * t + 2];
    const glm::ivec3 from = bucket_of(glm::min(a, glm::min(b, c)) - reach);
    const glm::ivec3 to = bucket_of(glm::max(a, glm::max(b, c)) + reach);
    for (int z = from.z; z <= to.z; ++z)
      for (int y = from.y; y <= to.y; ++y)
        for (int x = from.x; x <= to.x; ++x)
          bucket_triangles_[size_t(x) + size_t(buckets_.x) * (size_t(y) + size_t(buckets_.y) * z)].push_back(int(t));
    const glm::ivec3 col_from = bucket_of(glm::min(a, glm::min(b, c)));
    const glm::ivec3 col_to = bucket_of(glm::max(a, glm::max(b, c)));
    for (int y = col_from.y; y <= col_to.y; ++y)
      for (int x = col_from.x; x <= col_to.x; ++x) column_triangles_[size_t(x) + size_t(buckets_.x) * y].push_back(int(t));
  }
}

glm::ivec3 PlacedMesh::bucket_of(glm::vec3 p) const {
  return glm::clamp(glm::ivec3(glm::floor((p - lo_) / bucket_size_)), glm::ivec3(0), buckets_ - 1);
}

bool PlacedMesh::inside(glm::vec3 p) const {
  if (glm::any(glm::lessThan(p, lo_)) || glm::any(glm::greaterThan(p, hi_))) return false;
  // The winding number along the ray from p toward +z: each triangle above p whose projection
  // covers p adds the sign of its normal's z (+1 leaving the solid, -1 entering).
  // The ray is moved off p by a sliver at an odd angle, so one passing exactly through an edge or a
  // vertex (a lattice point on the mesh's axis) meets each surface once, not twice or never.
  const glm::vec3 extent = hi_ - lo_;
  p += glm::vec3(0.7316f, 0.4157f, 0.0f) * (1e-6f * std::max(extent.x, extent.y));
  const glm::ivec3 b = bucket_of(p);
  int winding = 0;
  for (int t : column_triangles_[size_t(b.x) + size_t(buckets_.x) * b.y]) {
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
  return winding != 0;
}

float PlacedMesh::distance(glm::vec3 p) const {
  const bool in = inside(p);
  float nearest = reach_;
  if (!(glm::any(glm::lessThan(p, lo_)) || glm::any(glm::greaterThan(p, hi_)))) {
    const glm::ivec3 b = bucket_of(p);
    for (int t : bucket_triangles_[size_t(b.x) + size_t(buckets_.x) * (size_t(b.y) + size_t(buckets_.y) * b.z)])
      nearest = std::min(nearest, triangle_distance(p, corners_[3 * t], corners_[3 * t + 1], corners_[3 * t + 2]));
  }
  return in ? -nearest : nearest;
}

}  // namespace liquid
