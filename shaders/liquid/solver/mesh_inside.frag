#version 450
// Mesh voxelization, inside pass: a surface crossing a cell's column between its centre and the
// next cell's up (the top cell: anywhere above it) adds +-1 by its facing, summed by additive
// blending into the mesh's channel. The field pass sums a cell's count and those above it: +-1
// inside, 0 outside (either sign: the winding's is not needed). In 2D the cells lie at z = 0, the
// mesh's cross-section, and count every surface above it.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/mesh_cell.glsl"

layout(location = 0) in float v_z;
layout(location = 3) flat in int v_slice;
layout(location = 0) out vec4 out_count;

void main() {
  ivec3 c;
  if (!mesh_fragment_cell(v_slice, c)) discard;
  float centre = cell_center(c).z;
  bool top = c.z == grid_cells().z - 1;
  if (v_z <= centre || (!top && v_z > centre + cell_size())) discard;
  out_count = vec4(0.0);
  out_count[pc.slot] = gl_FrontFacing ? 1.0 : -1.0;
}
