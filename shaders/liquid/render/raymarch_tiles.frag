#version 450
// Classifies the raymarch's screen tiles (one fragment each): LIQUID_RAYMARCH_TILE_LIQUID where any
// coarse ray a pixel of the tile reads met the liquid, LIQUID_RAYMARCH_TILE_MISS elsewhere.
// raymarch_tile.vert then draws each kind with its own pipeline.
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"

#include "liquid/render/raymarch_tiles.glsl"

layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform RaymarchBlock {
  RaymarchUniforms r;
};
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_COARSE) uniform sampler2D u_coarse;  // nearest

layout(location = 0) in vec2 v_uv;  // fullscreen.vert's, unused
layout(location = 0) out uint out_kind;

void main() {
  ivec2 tile = ivec2(gl_FragCoord.xy);
  ivec2 first = coarse_ray_before(tile * LIQUID_RAYMARCH_TILE_PIXELS);
  ivec2 last = ivec2(r.coarse_width, r.coarse_height) - 1;
  float nearest = LIQUID_RAYMARCH_NO_CROSSING;
  for (int y = 0; y < k_tile_coarse_rays; ++y)
    for (int x = 0; x < k_tile_coarse_rays; ++x)
      nearest = min(nearest, texelFetch(u_coarse, clamp(first + ivec2(x, y), ivec2(0), last), 0).r);
  out_kind = nearest < LIQUID_RAYMARCH_NO_CROSSING ? LIQUID_RAYMARCH_TILE_LIQUID : LIQUID_RAYMARCH_TILE_MISS;
}
