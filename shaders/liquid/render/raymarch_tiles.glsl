// The raymarch's coarse rays and screen tiles (LIQUID_RAYMARCH_COARSE_PIXELS and
// LIQUID_RAYMARCH_TILE_PIXELS of view_blocks.h). Coarse texel a holds the ray through the viewport's
// pixel coordinate S a + S / 2 (S the coarse pixels): the corner its S x S block of pixels shares.
#ifndef LIQUID_RAYMARCH_TILES_GLSL
#define LIQUID_RAYMARCH_TILES_GLSL

// Per axis, the coarse ray before a pixel's centre; the next texel holds the one after it.
ivec2 coarse_ray_before(ivec2 pixel) {
  return ivec2(floor((vec2(pixel) + 0.5) / float(LIQUID_RAYMARCH_COARSE_PIXELS) - 0.5));
}

// The coarse rays a tile's pixels read, per axis: from the one before its first pixel to the one
// after its last.
const int k_tile_coarse_rays = LIQUID_RAYMARCH_TILE_PIXELS / LIQUID_RAYMARCH_COARSE_PIXELS + 2;

#endif
