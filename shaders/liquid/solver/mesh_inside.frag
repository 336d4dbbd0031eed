#version 450
// Mesh voxelization, inside pass: a cell is inside the closed mesh when the surfaces above it (toward
// +z) do not cancel: each adds +-1 by its facing, summed by additive blending into the mesh's
// channel, so the count is +-1 inside and 0 outside (either sign: the winding's is not needed).
// In 2D the cells lie at z = 0, the mesh's cross-section.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/mesh_cell.glsl"

layout(location = 0) in float v_z;
layout(location = 3) flat in int v_slice;
layout(location = 0) out vec4 out_count;

void main() {
  ivec3 c;
  if (!mesh_fragment_cell(v_slice, c) || v_z <= cell_center(c).z) discard;
  out_count = vec4(0.0);
  out_count[pc.slot] = gl_FrontFacing ? 1.0 : -1.0;
}
