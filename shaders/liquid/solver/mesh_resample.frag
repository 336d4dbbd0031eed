#version 450
// Mesh resample pass (3D): a mesh's field at its pose, from its reference field (its distance
// voxelized once, at the reference placement; liquid/solver/mesh_field.h). Drawn over the mesh's
// box at the pose, each cell reads the reference trilinearly where the same point of the mesh lies
// in the reference placement (rotation and translation keep distances), clamped to the field's
// band (the reference's reaches a cell further), into the mesh's channel; the other channels get LIQUID_MESH_FAR, which the MIN blending
// leaves as they are.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_MESH_REFERENCE) uniform GRID_SAMPLER u_reference;
layout(push_constant) uniform Push {
  MeshResamplePush pc;
};
layout(location = 0) out vec4 out_value;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) discard;  // the atlas's unused tiles (the box's scissor keeps them out)
  vec3 q = (pc.reference_from_world * vec4(cell_center(c), 1.0)).xyz;
  out_value = vec4(LIQUID_MESH_FAR);
  out_value[pc.slot] = clamp(sample_grid_linear(u_reference, q).r, -pc.band, pc.band);
}
