#version 450
// Mesh voxelization, field pass: one full-screen grid pass (grid_fragment.glsl) joining the inside
// counts and the band's distances into the signed distance the solver samples (common.glsl's
// mesh_distance): -d inside, d outside, d at most `band` (the cleared value beyond every triangle's reach).
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_MESH_INSIDE) uniform GRID_SAMPLER u_inside;
layout(set = 0, binding = LIQUID_BINDING_MESH_BAND) uniform GRID_SAMPLER u_band;
layout(push_constant) uniform Push {
  MeshRasterPush pc;
};
layout(location = 0) out vec4 out_field;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) {
    out_field = vec4(0.0);
    return;
  }
  vec4 count = fetch_grid(u_inside, c);
  vec4 d = min(fetch_grid(u_band, c), vec4(pc.band));
  out_field = mix(d, -d, greaterThan(abs(count), vec4(0.5)));
}
