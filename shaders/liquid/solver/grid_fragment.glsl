// The cell a fragment of a full-screen grid pass computes (grid.frag, pressure.frag, potential.frag),
// on every path of liquid/solver/grid_layout.h: in 2D and in the atlas it follows from the fragment's
// position; on the layered paths the slice comes from the layered full-screen pair (v_layer).
// Include after common.glsl.
#ifndef LIQUID_GRID_FRAGMENT_GLSL
#define LIQUID_GRID_FRAGMENT_GLSL

layout(location = 0) in vec2 v_uv;
#if DIM == 3 && !ATLAS
layout(location = 1) flat in int v_layer;
#endif

// False for the atlas's unused tiles past the last slice (nothing reads them; they are written as 0).
bool grid_fragment_cell(out ivec3 c) {
#if DIM == 3 && ATLAS
  c = atlas_cell(ivec2(gl_FragCoord.xy), grid_cells(), atlas_tiles());
  return c.z < grid_cells().z;
#elif DIM == 3
  c = ivec3(ivec2(gl_FragCoord.xy), v_layer);
  return true;
#else
  c = ivec3(ivec2(gl_FragCoord.xy), 0);
  return true;
#endif
}

#endif
