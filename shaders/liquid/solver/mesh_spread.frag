#version 450
// Mesh voxelization, spread and field passes: drawn over the mesh's box only (the cells within the
// band of its bounds), each cell takes, of the closest surface points held by some cells around it
// (itself included), the one closest to its centre.
//   FIELD=0  the spread passes, one per axis: the cells up to `reach` away along it. Together they
//            carry a seed's point to the band's edge (a separable jump flood of one step), but a
//            cell can be left with a point that was the closest for its neighbour along the way.
//   FIELD=1  the field pass: the 3x3(x3) neighbourhood, which mends most of those, then the field:
//            the distance to the point, clamped to the band, negative where the crossing counts
//            (mesh_inside.frag) from the cell up do not cancel, in the mesh's channel; the other
//            channels get LIQUID_MESH_FAR, which the MIN blending leaves as they are.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/solver/grid_fragment.glsl"

layout(set = 0, binding = LIQUID_BINDING_MESH_NEAREST) uniform GRID_SAMPLER u_nearest;
#if FIELD
layout(set = 0, binding = LIQUID_BINDING_MESH_INSIDE) uniform GRID_SAMPLER u_inside;
#endif
layout(push_constant) uniform Push {
  MeshRasterPush pc;
};
layout(location = 0) out vec4 out_value;

// Of the closest points held by the cells `first` to `last` from c (inclusive, per axis), the one
// closest to c's centre, and its distance.
void closest_of(ivec3 c, ivec3 first, ivec3 last, out vec3 nearest, out float best) {
  vec3 centre = cell_center(c);
  nearest = vec3(LIQUID_MESH_FAR);
  best = LIQUID_MESH_FAR;
  for (int z = first.z; z <= last.z; ++z)
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) {
        vec3 q = fetch_grid(u_nearest, c + ivec3(x, y, z)).xyz;
        float d = distance(centre, q);
        if (d < best) {
          best = d;
          nearest = q;
        }
      }
}

void main() {
  ivec3 c;
  if (!grid_fragment_cell(c)) discard;  // the atlas's unused tiles (the box's scissor keeps them out)
  // The search, kept within the box (the cells outside it hold nothing of this voxelization).
  ivec3 lo = pc.box_min.xyz - c, hi = pc.box_max.xyz - 1 - c;
  vec3 nearest;
  float best;
#if FIELD
  closest_of(c, max(lo, ivec3(-1)), min(hi, ivec3(1)), nearest, best);
  vec4 count = vec4(0.0);
  for (int z = c.z; z < pc.box_max.z; ++z) count += fetch_grid(u_inside, ivec3(c.xy, z));
  float d = min(best, pc.band);
  out_value = vec4(LIQUID_MESH_FAR);
  out_value[pc.slot] = abs(count[pc.slot]) > 0.5 ? -d : d;
#else
  ivec3 reach = ivec3(equal(ivec3(pc.axis), ivec3(0, 1, 2))) * pc.reach;
  closest_of(c, max(lo, -reach), min(hi, reach), nearest, best);
  out_value = vec4(nearest, 0.0);
#endif
}
