#include "liquid/analysis/energy_budget.h"

#include "shaders/liquid/shared.h"

#include <cmath>
#include <stdexcept>

namespace liquid {

void EnergyBudget::add(const EnergyBudget& o) {
  kinetic += o.kinetic;
  potential += o.potential;
  gravity_work += o.gravity_work;
  pressure_and_grid_walls += o.pressure_and_grid_walls;
  pic += o.pic;
  particle_walls += o.particle_walls;
}

namespace {

using gpu::k_fluid_epsilon;

// grid_sample.glsl's sample_grid(): (bi/tri)linear between cell centres over the cells holding liquid.
struct GridSampler {
  const SimulationSetup& setup;
  const std::vector<glm::vec4>& splat;
  const std::vector<glm::vec4>& velocity;

  size_t index(glm::ivec3 c) const {
    c = glm::clamp(c, glm::ivec3(0), setup.grid_cells - 1);
    return (size_t(c.z) * size_t(setup.grid_cells.y) + size_t(c.y)) * size_t(setup.grid_cells.x) + size_t(c.x);
  }

  void sample(glm::vec3 x, glm::vec3& u_new, glm::vec3& u_old) const {
    glm::vec3 g = x / setup.cell_size - 0.5f;
    glm::ivec3 base(glm::floor(g));
    glm::vec3 f = g - glm::vec3(base);
    const int corners = setup.dimension == 3 ? 8 : 4;
    if (setup.dimension == 2) f.z = 0.0f, base.z = 0;
    u_new = u_old = glm::vec3(0.0f);
    float total = 0.0f;
    for (int i = 0; i < corners; ++i) {
      const glm::ivec3 o(i & 1, (i >> 1) & 1, (i >> 2) & 1);
      const glm::vec3 t = glm::mix(1.0f - f, f, glm::vec3(o));
      const float weight = t.x * t.y * t.z;
      if (weight <= 0.0f) continue;
      const size_t cell = index(base + o);
      if (velocity[cell].a < 0.5f) continue;
      total += weight;
      u_new += weight * glm::vec3(velocity[cell]);
      u_old += weight * glm::vec3(splat[cell]) / std::max(splat[cell].a, k_fluid_epsilon);
    }
    if (total > 0.0f) u_new /= total, u_old /= total;
  }

  // grid_sample.glsl's fit_grid_affine(): the value at x of the weighted least-squares fit of a
  // linear field to the cells within the kernel's radius that hold liquid, with the splat's weights
  // (1 - d^2/r^2)^3, d in cells. False where the fit's normal matrix is singular (the shader then
  // reads bilinearly).
  bool fit(glm::vec3 x, glm::vec3& u_new, glm::vec3& u_old) const {
    const double r = setup.kernel_radius_cells;
    glm::dvec3 g = glm::dvec3(x) / double(setup.cell_size) - 0.5;
    const bool flat = setup.dimension == 2;
    if (flat) g.z = 0.0;
    const glm::ivec3 n = setup.grid_cells;
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(g - r)), glm::ivec3(0));
    glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(g + r)), n - 1);
    glm::ivec3 first = lo;
    if (flat) first.z = hi.z = 0;
    glm::dmat4 normal(0.0);
    glm::dmat3x4 fit_new(0.0), fit_old(0.0);  // per component, sum w u b
    for (int z = first.z; z <= hi.z; ++z)
      for (int y = first.y; y <= hi.y; ++y)
        for (int xi = first.x; xi <= hi.x; ++xi) {
          const glm::dvec3 d = glm::dvec3(xi, y, z) - g;
          const double t = 1.0 - glm::dot(d, d) / (r * r);
          if (t <= 0.0) continue;
          const size_t cell = index({xi, y, z});
          if (velocity[cell].a < 0.5f) continue;
          const double w = t * t * t;
          const glm::dvec4 b(1.0, d);
          normal += w * glm::outerProduct(b, b);
          const glm::dvec3 s = glm::dvec3(splat[cell]) / double(std::max(splat[cell].a, k_fluid_epsilon));
          for (int j = 0; j < 3; ++j) {
            fit_new[j] += w * double(velocity[cell][j]) * b;
            fit_old[j] += w * s[j] * b;
          }
        }
    if (flat) normal[3][3] = 1.0;  // no z: its coefficient is zero
    if (std::abs(glm::determinant(normal)) < 1e-6) return false;
    const glm::dmat4 solve = glm::inverse(normal);
    for (int j = 0; j < 3; ++j) {
      u_new[j] = float((solve * fit_new[j])[0]);
      u_old[j] = float((solve * fit_old[j])[0]);
    }
    return true;
  }
};

}  // namespace

EnergyBudget step_energy_budget(const SimulationSetup& setup, double pic_step, const ParticleSnapshot& before,
                                const ParticleSnapshot& after, const std::vector<glm::vec4>& splat,
                                const std::vector<glm::vec4>& grid_velocity, Transfer transfer) {
  const size_t cells = size_t(setup.grid_cells.x) * setup.grid_cells.y * setup.grid_cells.z;
  if (before.positions.size() != after.positions.size() || splat.size() != cells || grid_velocity.size() != cells)
    throw std::invalid_argument("step_energy_budget: the particles or the grids do not match the setup");
  const GridSampler grid{setup, splat, grid_velocity};
  const glm::dvec3 g(setup.gravity), g_dt = g * double(setup.time_step);
  const double m = setup.particle_mass;
  EnergyBudget b;
  for (size_t i = 0; i < before.positions.size(); ++i) {
    const glm::dvec3 x0(before.positions[i]), x1(after.positions[i]);
    const glm::dvec3 v0(before.velocities[i]), v1(after.velocities[i]);
    glm::vec3 u_new, u_old;
    if (transfer != Transfer::Affine || !grid.fit(glm::vec3(x0), u_new, u_old)) grid.sample(glm::vec3(x0), u_new, u_old);
    const glm::dvec3 increment = glm::dvec3(u_new) - glm::dvec3(u_old);
    const glm::dvec3 pull = pic_step * (glm::dvec3(u_old) - v0);
    const glm::dvec3 blended = v0 + increment + pull;
    // The work of each part of the change, each taken at the mean of the velocities it acts
    // between so that the parts add up to the kinetic energy's change.
    const glm::dvec3 mid_increment = v0 + 0.5 * increment;
    b.gravity_work += m * glm::dot(mid_increment, g_dt);
    b.pressure_and_grid_walls += m * glm::dot(mid_increment, increment - g_dt);
    const glm::dvec3 after_increment = v0 + increment;
    b.pic += 0.5 * m * (glm::dot(blended, blended) - glm::dot(after_increment, after_increment));
    b.particle_walls += 0.5 * m * (glm::dot(v1, v1) - glm::dot(blended, blended));
    b.kinetic += 0.5 * m * (glm::dot(v1, v1) - glm::dot(v0, v0));
    b.potential -= m * glm::dot(g, x1 - x0);
  }
  return b;
}

}  // namespace liquid
