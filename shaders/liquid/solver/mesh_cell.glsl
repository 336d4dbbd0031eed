// The cell a fragment of the mesh raster passes (mesh_raster.vert) lands in, and whether it belongs to
// the slice the primitive was drawn for: in the atlas a triangle spills into the neighbouring tiles,
// other slices, which must not receive it. Include after common.glsl.
#ifndef LIQUID_MESH_CELL_GLSL
#define LIQUID_MESH_CELL_GLSL

layout(push_constant) uniform Push {
  MeshRasterPush pc;
};

bool mesh_fragment_cell(int slice, out ivec3 c) {
#if DIM == 3 && ATLAS
  c = atlas_cell(ivec2(gl_FragCoord.xy), grid_cells(), atlas_tiles());
  return c.z == slice;
#else
  c = ivec3(ivec2(gl_FragCoord.xy), slice);
  return true;
#endif
}

#endif
