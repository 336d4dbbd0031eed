#version 450
// Body grid pass: the grid pass's u' (grid_update.glsl) without one dynamic obstacle (the push
// constant's), i.e. what the liquid would have done this step had that body not been there. The
// body reaction pass compares it with the grid pass's u' at every particle.
#extension GL_GOOGLE_include_directive : require
#define LIQUID_BODIES
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"
#include "liquid/solver/grid_update.glsl"

layout(push_constant) uniform BodyGridPush {
  int excluded;  // the obstacle left out
} pc;

layout(location = 0) out vec4 out_velocity;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_velocity = vec4(0.0);
    return;
  }
  vec4 splat = fetch_grid(u_splat, c);
  out_velocity = vec4(grid_update(c, splat, pc.excluded), splat.a > k_fluid_epsilon ? 1.0 : 0.0);
}
