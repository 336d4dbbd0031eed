#version 450
// Mesh voxelization, spread and field passes (a jump flood): drawn over the mesh's box only (the
// cells within the band of its bounds), each cell takes, of the closest surface points held by the
// cells `step` apart around it (itself included), the one closest to its centre.
//   FIELD=0  the spread passes, steps halving down to 1 (mesh_field.cpp), which carry the seeds'
//            points to the band's edge.
//   FIELD=1  the field pass, one more of step 1 (which mends most cells the halving steps left
//            with a neighbour's point), then the field: the distance to the point, clamped to the
//            band, negative where the crossing counts (mesh_inside.frag) from the cell up do not
//            cancel, in the mesh's channel; the other channels get LIQUID_MESH_FAR, which the MIN
//            blending leaves as they are. With REFERENCE=1 the distance alone, into the mesh's
//            reference field (mesh_field.h), which mesh_resample.frag then places at each pose.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

#ifndef REFERENCE
#define REFERENCE 0
#endif

layout(set = 0, binding = LIQUID_BINDING_MESH_NEAREST) uniform GRID_SAMPLER u_nearest;
#if FIELD
layout(set = 0, binding = LIQUID_BINDING_MESH_INSIDE) uniform GRID_SAMPLER u_inside;
#endif
layout(push_constant) uniform Push {
  MeshRasterPush pc;
};
layout(location = 0) out vec4 out_value;

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) discard;  // the atlas's unused tiles (the box's scissor keeps them out)
  vec3 centre = cell_center(c);
  // The 3x3x3 cells `step` apart around c (3x3 in 2D), each clamped into the box: the cells outside
  // it hold nothing of this voxelization (a clamped one is read twice, which changes nothing).
  vec3 nearest = vec3(LIQUID_MESH_FAR);
  float best = LIQUID_MESH_FAR;
  [[unroll]] for (int z = DIM == 3 ? -1 : 0; z <= (DIM == 3 ? 1 : 0); ++z)
    [[unroll]] for (int y = -1; y <= 1; ++y)
      [[unroll]] for (int x = -1; x <= 1; ++x) {
        ivec3 n = clamp(c + ivec3(x, y, z) * pc.step, pc.box_min.xyz, pc.box_max.xyz - 1);
        vec3 q = fetch_grid(u_nearest, n).xyz;
        float d = distance(centre, q);
        if (d < best) {
          best = d;
          nearest = q;
        }
      }
#if FIELD
  vec4 count = vec4(0.0);
  for (int z = c.z; z < pc.box_max.z; ++z) count += fetch_grid(u_inside, ivec3(c.xy, z));
  float d = min(best, pc.band);
  float signed_distance = abs(count[pc.slot]) > 0.5 ? -d : d;
#if REFERENCE
  out_value = vec4(signed_distance);  // the mesh's own reference field (R32F: one channel)
#else
  out_value = vec4(LIQUID_MESH_FAR);
  out_value[pc.slot] = signed_distance;
#endif
#else
  out_value = vec4(nearest, 0.0);
#endif
}
