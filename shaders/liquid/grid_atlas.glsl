// A 3D grid stored as a 2D atlas of its slices (the "atlas" path, liquid/solver/grid_layout.h): slice z of
// a grid of `cells` is the tile (z % tiles.x, z / tiles.x) of an image of cells.xy * tiles texels.
// The one place shaders map cells to atlas texels and back, and interpolate across slices.
// The divisions are done in float: lavapipe has no vector integer division, so an int one runs
// lane by lane (it made the atlas's splat twice as slow). Quotients of integers below 2^16 offset
// by half a unit are never within rounding of a whole number, so floor() is exact here.
#ifndef LIQUID_GRID_ATLAS_GLSL
#define LIQUID_GRID_ATLAS_GLSL

// The first texel of slice z's tile.
ivec2 atlas_tile_origin(int z, ivec3 cells, ivec2 tiles) {
  float row = floor((float(z) + 0.5) / float(tiles.x));
  return ivec2(z - int(row) * tiles.x, int(row)) * cells.xy;
}

ivec2 atlas_texel(ivec3 c, ivec3 cells, ivec2 tiles) { return c.xy + atlas_tile_origin(c.z, cells, tiles); }

// The cell an atlas texel holds; z >= cells.z in the unused tiles past the last slice.
ivec3 atlas_cell(ivec2 texel, ivec3 cells, ivec2 tiles) {
  ivec2 tile = ivec2(floor((vec2(texel) + 0.5) / vec2(cells.xy)));
  return ivec3(texel - tile * cells.xy, tile.y * tiles.x + tile.x);
}

// What a linear, clamp-to-edge sampler3D returns at normalised coordinates uvw: hardware bilinear
// inside the two nearest slices' tiles (clamped half a texel inside each tile, so a lookup never
// blends in a neighbouring slice), then linear between the slices by hand. `s` has linear filtering.
vec4 atlas_sample_linear(sampler2D s, vec3 uvw, ivec3 cells, ivec2 tiles) {
  vec2 xy = clamp(uvw.xy * vec2(cells.xy), vec2(0.5), vec2(cells.xy) - 0.5);
  float z = clamp(uvw.z * float(cells.z) - 0.5, 0.0, float(cells.z - 1));
  int z0 = int(floor(z));
  int z1 = min(z0 + 1, cells.z - 1);
  vec2 inv_size = 1.0 / vec2(cells.xy * tiles);
  vec4 a = textureLod(s, (vec2(atlas_tile_origin(z0, cells, tiles)) + xy) * inv_size, 0.0);
  vec4 b = textureLod(s, (vec2(atlas_tile_origin(z1, cells, tiles)) + xy) * inv_size, 0.0);
  return mix(a, b, z - float(z0));
}

#endif
