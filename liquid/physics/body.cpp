#include "liquid/physics/body.h"

#include <algorithm>
#include <cmath>

namespace liquid {

namespace {

// Eberly's per-triangle sums of one coordinate's three values.
struct Subexpressions {
  double f1, f2, f3, g0, g1, g2;
};
Subexpressions subexpressions(double w0, double w1, double w2) {
  const double t0 = w0 + w1, t1 = w0 * w0, t2 = t1 + w1 * t0;
  Subexpressions s;
  s.f1 = t0 + w2;
  s.f2 = t2 + w2 * s.f1;
  s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

// The mesh's vertex `i` with its scale, in double.
glm::dvec3 scaled_vertex(const TriangleMesh& mesh, uint32_t i) { return glm::dvec3(mesh.vertices[i]) * double(mesh.scale); }

}  // namespace

MeshMass mesh_mass_properties(const TriangleMesh& mesh) {
  // The integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx over the solid.
  double integral[10] = {};
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = scaled_vertex(mesh, mesh.indices[t]), b = scaled_vertex(mesh, mesh.indices[t + 1]),
                     c = scaled_vertex(mesh, mesh.indices[t + 2]);
    const glm::dvec3 d = glm::cross(b - a, c - a);
    const Subexpressions x = subexpressions(a.x, b.x, c.x), y = subexpressions(a.y, b.y, c.y),
                         z = subexpressions(a.z, b.z, c.z);
    integral[0] += d.x * x.f1;
    integral[1] += d.x * x.f2;
    integral[2] += d.y * y.f2;
    integral[3] += d.z * z.f2;
    integral[4] += d.x * x.f3;
    integral[5] += d.y * y.f3;
    integral[6] += d.z * z.f3;
    integral[7] += d.x * (a.y * x.g0 + b.y * x.g1 + c.y * x.g2);
    integral[8] += d.y * (a.z * y.g0 + b.z * y.g1 + c.z * y.g2);
    integral[9] += d.z * (a.x * z.g0 + b.x * z.g1 + c.x * z.g2);
  }
  const double scale[10] = {1.0 / 6, 1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 60, 1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (int k = 0; k < 10; ++k) integral[k] *= scale[k];
  MeshMass m;
  m.volume = integral[0];
  if (!(m.volume > 0.0)) return m;
  const glm::dvec3 cm = glm::dvec3(integral[1], integral[2], integral[3]) / m.volume;
  m.centroid = cm;
  const double v = m.volume;
  const double xx = integral[5] + integral[6] - v * (cm.y * cm.y + cm.z * cm.z);
  const double yy = integral[4] + integral[6] - v * (cm.z * cm.z + cm.x * cm.x);
  const double zz = integral[4] + integral[5] - v * (cm.x * cm.x + cm.y * cm.y);
  const double xy = -(integral[7] - v * cm.x * cm.y);
  const double yz = -(integral[8] - v * cm.y * cm.z);
  const double zx = -(integral[9] - v * cm.z * cm.x);
  m.inertia = glm::dmat3(xx, xy, zx, xy, yy, yz, zx, yz, zz);  // symmetric: columns are rows
  return m;
}

PrincipalAxes principal_axes(const glm::dmat3& inertia) {
  // Cyclic Jacobi rotations: a[col][row] as glm stores it; symmetric, so either reads.
  glm::dmat3 a = inertia, v(1.0);
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-30 * diagonal) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        glm::dmat3 j(1.0);  // the rotation in the (p, q) plane
        j[p][p] = c;
        j[q][q] = c;
        j[q][p] = s;   // column q, row p
        j[p][q] = -s;  // column p, row q
        a = glm::transpose(j) * a * j;
        v = v * j;
      }
  }
  if (glm::determinant(v) < 0.0) v[2] = -v[2];  // a rotation, not a reflection
  PrincipalAxes axes;
  axes.moments = glm::dvec3(a[0][0], a[1][1], a[2][2]);
  axes.axes = glm::normalize(glm::quat_cast(v));
  return axes;
}

Obstacle mesh_body_in_principal_frame(const Obstacle& obstacle) {
  if (!obstacle.dynamic || obstacle.shape != ObstacleShape::Mesh) return obstacle;
  Obstacle o = obstacle;
  const MeshMass mass = mesh_mass_properties(o.mesh);
  const PrincipalAxes principal = principal_axes(mass.inertia);
  // world = center + R (s v) = (center + R c) + (R P) (s P^T (v - c / s)), P the principal axes.
  const glm::dvec3 c_local = mass.centroid / double(o.mesh.scale);
  const glm::dquat to_principal = glm::inverse(principal.axes);
  for (glm::vec3& vertex : o.mesh.vertices) vertex = glm::vec3(to_principal * (glm::dvec3(vertex) - c_local));
  const glm::quat rotation = o.mesh.rotation;
  o.center = obstacle.center + rotation * glm::vec3(mass.centroid);
  o.rotation = glm::normalize(rotation * glm::quat(principal.axes));
  o.mesh.rotation = o.rotation;
  return o;
}

double body_volume(const Obstacle& o, int dimension) {
  if (o.shape == ObstacleShape::Mesh) return mesh_mass_properties(o.mesh).volume;
  const glm::dvec3 e(o.half_extent);
  const double r = o.radius;
  if (o.shape == ObstacleShape::Box) return dimension == 2 ? 4.0 * e.x * e.y : 8.0 * e.x * e.y * e.z;
  return dimension == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
}

double body_surface(const Obstacle& o, int dimension) {
  if (o.shape == ObstacleShape::Mesh) {
    double area = 0.0;
    for (size_t t = 0; t + 2 < o.mesh.indices.size(); t += 3) {
      const glm::dvec3 a = scaled_vertex(o.mesh, o.mesh.indices[t]), b = scaled_vertex(o.mesh, o.mesh.indices[t + 1]),
                       c = scaled_vertex(o.mesh, o.mesh.indices[t + 2]);
      area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
  }
  const glm::dvec3 e(o.half_extent);
  const double r = o.radius;
  if (o.shape == ObstacleShape::Box) return dimension == 2 ? 4.0 * (e.x + e.y) : 8.0 * (e.x * e.y + e.y * e.z + e.x * e.z);
  return dimension == 2 ? 2.0 * M_PI * r : 4.0 * M_PI * r * r;
}

double body_mass(const Obstacle& o, int dimension) {
  return o.mass > 0.0f ? double(o.mass) : double(o.density) * body_volume(o, dimension);
}

glm::vec3 body_inertia(const Obstacle& o, int dimension) {
  const double m = body_mass(o, dimension);
  if (o.shape == ObstacleShape::Mesh) {
    const MeshMass mass = mesh_mass_properties(o.mesh);
    const double density = m / mass.volume;
    return glm::vec3(glm::dvec3(mass.inertia[0][0], mass.inertia[1][1], mass.inertia[2][2]) * density);
  }
  const glm::dvec3 e2 = glm::dvec3(o.half_extent) * glm::dvec3(o.half_extent);
  const double r2 = double(o.radius) * o.radius;
  if (dimension == 2) {
    // A rectangle of sides 2a, 2b: m (a^2 + b^2) / 3; a disc: m r^2 / 2.
    const double iz = o.shape == ObstacleShape::Box ? m * (e2.x + e2.y) / 3.0 : 0.5 * m * r2;
    return glm::vec3(float(iz));
  }
  if (o.shape == ObstacleShape::Box) return glm::vec3(glm::dvec3(e2.y + e2.z, e2.x + e2.z, e2.x + e2.y) * (m / 3.0));
  return glm::vec3(float(0.4 * m * r2));
}

double body_added_mass(const Obstacle& o, int dimension, double liquid_density, double cell_size) {
  return liquid_density * (body_volume(o, dimension) + body_surface(o, dimension) * cell_size);
}

float body_shape_half_size(const Obstacle& o, float kernel_radius_cells, float cell_size) {
  float farthest = 0.0f;
  for (const glm::vec3& v : o.mesh.vertices) farthest = std::max(farthest, glm::length(v) * o.mesh.scale);
  return farthest + (kernel_radius_cells + 3.0f) * cell_size;
}

double body_added_inertia_ratio(const Obstacle& o, int dimension, double added_mass) {
  const glm::vec3 e = dimension == 2 ? glm::vec3(glm::vec2(o.half_extent), 0.0f) : o.half_extent;
  double radius = o.shape == ObstacleShape::Box ? double(glm::length(e)) : double(o.radius);
  if (o.shape == ObstacleShape::Mesh) {  // about the centre of mass (the principal frame's origin)
    const glm::dvec3 centroid = mesh_mass_properties(o.mesh).centroid;
    radius = 0.0;
    for (uint32_t i = 0; i < uint32_t(o.mesh.vertices.size()); ++i)
      radius = std::max(radius, glm::length(scaled_vertex(o.mesh, i) - centroid));
  }
  const glm::vec3 inertia = body_inertia(o, dimension);
  return added_mass * radius * radius / double(std::min(inertia.x, std::min(inertia.y, inertia.z)));
}

glm::vec3 mesh_half_extent(const TriangleMesh& mesh) {
  glm::vec3 e(0.0f);
  for (const glm::vec3& v : mesh.vertices) e = glm::max(e, glm::abs(v) * mesh.scale);
  return e;
}

glm::vec3 body_wall_half_extent(const Obstacle& o) {
  if (o.shape == ObstacleShape::Sphere) return glm::vec3(o.radius);
  const glm::vec3 e = o.shape == ObstacleShape::Mesh ? mesh_half_extent(o.mesh) : o.half_extent;
  const glm::mat3 turn = glm::mat3_cast(o.rotation);
  return glm::abs(turn[0]) * e.x + glm::abs(turn[1]) * e.y + glm::abs(turn[2]) * e.z;
}

}  // namespace liquid
