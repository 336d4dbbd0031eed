#version 450
// The raymarch's screen tiles of one kind (raymarch_tiles.frag): one point sprite per tile,
// LIQUID_RAYMARCH_TILE_PIXELS wide, drawn with gl_VertexIndex alone (no vertex buffer); a tile of
// the other kind is placed outside the view and draws nothing. Points, not two triangles a tile:
// a rasterizer that shades blocks of 4x4 pixels (lavapipe) shades each block a triangle's diagonal
// cuts twice, and the tiles then cost half again as much. The viewport spans the tiles whole (the
// scissor cuts them to the view), so that every point's centre lies inside it.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"

layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform RaymarchBlock {
  RaymarchUniforms r;
};
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_TILES) uniform usampler2D u_tiles;
// raymarch.frag's: the pipeline without the liquid draws the tiles no coarse ray saw it in.
layout(constant_id = LIQUID_RAYMARCH_BACKGROUND_ONLY_ID) const bool BACKGROUND_ONLY = false;

void main() {
  ivec2 tile = ivec2(gl_VertexIndex % r.tiles_x, gl_VertexIndex / r.tiles_x);
  uint kind = texelFetch(u_tiles, tile, 0).r;
  bool drawn = BACKGROUND_ONLY ? kind == LIQUID_RAYMARCH_TILE_MISS : kind != LIQUID_RAYMARCH_TILE_MISS;
  vec2 centre = (vec2(tile) + 0.5) / vec2(r.tiles_x, r.tiles_y);
  gl_Position = drawn ? vec4(centre * 2.0 - 1.0, 0.0, 1.0) : vec4(-2.0, -2.0, 0.0, 1.0);
  gl_PointSize = float(LIQUID_RAYMARCH_TILE_PIXELS);
}
