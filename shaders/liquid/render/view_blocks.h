// The views' own uniform and push-constant blocks, written once for the C++ that fills them
// (liquid/render/*.cpp) and the shaders that read them (shaders/liquid/render/*). Same rules as
// shared.h: C++ types are glm's, LIQUID_STRUCT blocks are std140, LIQUID_PUSH blocks std430.
#ifndef LIQUID_VIEW_BLOCKS_H
#define LIQUID_VIEW_BLOCKS_H

#include "../shared.h"

// Raymarch: the specialization constant that makes it draw the liquid alone over a host's targets
// (its id follows the scene's constants of common.glsl; raymarch.cpp checks that), and the one that
// leaves out the march and the liquid for the screen tiles no coarse ray saw liquid in.
#define LIQUID_RAYMARCH_COMPOSITE_ID 14
#define LIQUID_RAYMARCH_BACKGROUND_ONLY_ID 15
// Compositing: how the colour is written for the host's target format (LIQUID_RAYMARCH_OUTPUT_ID):
// display-encoded (UNORM targets), linear for an sRGB target (the hardware encodes it), or linear
// radiance times the exposure for an HDR float target.
#define LIQUID_RAYMARCH_OUTPUT_ID 16
#define LIQUID_OUTPUT_DISPLAY 0
#define LIQUID_OUTPUT_LINEAR 1
#define LIQUID_OUTPUT_HDR 2

// The raymarch's first pass marches one ray per LIQUID_RAYMARCH_COARSE_PIXELS^2 pixels (the ray
// through the corner their block shares); a second classifies screen tiles of
// LIQUID_RAYMARCH_TILE_PIXELS^2 pixels by whether any coarse ray around them met the liquid: tiles
// that met none are drawn without the liquid's code, the others march from just before the nearest
// crossing their coarse neighbours found (raymarch.cpp, raymarch_tiles.glsl).
#define LIQUID_RAYMARCH_COARSE_PIXELS 4
#define LIQUID_RAYMARCH_TILE_PIXELS 8
#define LIQUID_RAYMARCH_NO_CROSSING 1e30  // a coarse ray's distance where it met no liquid
#define LIQUID_RAYMARCH_TILE_MISS 0u
#define LIQUID_RAYMARCH_TILE_LIQUID 1u

// The tank's frame (tank_frame.vert): the domain box's 12 edges, a quad of 6 vertices each.
#define LIQUID_TANK_FRAME_BARS 12
#define LIQUID_TANK_FRAME_BAR_VERTICES 6

// 2D view: the specialization constant that draws the liquid (and obstacles) alone, with alpha,
// into a rectangle of a host's target (its id follows the scene's constants of common.glsl).
#define LIQUID_VIEW2D_PANEL_ID 14

// Height field: which mesh a draw makes.
#define LIQUID_HEIGHT_FIELD_GROUND 0
#define LIQUID_HEIGHT_FIELD_WATER 1

#ifdef __cplusplus
namespace liquid::gpu {
#endif

// Raymarch (raymarch.frag), at LIQUID_BINDING_VIEW_UNIFORMS.
LIQUID_STRUCT(RaymarchUniforms) {
  mat4 inverse_view_projection;
  mat4 view_projection;
  vec3 sun_direction;      // towards the sun, unit
  float iso_level;         // the surface: rho / rho0 crosses this
  ivec3 bricks;            // occupancy volume size
  float brick_cells;       // occupancy brick edge, cells
  float fine_step_cells;   // march step inside occupied bricks
  int brick_columns;       // the atlas path: the occupancy atlas's tiles (liquid/solver/grid_layout.h);
  int brick_rows;          // 1 and 1 otherwise
  float near_depth;        // clip-space depth of the near plane: 0, or 1 for reversed Z
  float exposure;          // compositing into an HDR target: the liquid's radiance times this
  float viewport_x;        // the view's viewport origin, pixels: per-pixel noise is placed relative
  float viewport_y;        // to it, so a view draws the same pixels wherever its viewport lies
  float viewport_width;    // the view's viewport size, pixels
  float viewport_height;
  int coarse_width;        // the coarse march's image, texels (LIQUID_RAYMARCH_COARSE_PIXELS)
  int coarse_height;
  int tiles_x;             // the screen tiles across the viewport (LIQUID_RAYMARCH_TILE_PIXELS)
  int tiles_y;
};

// Occupancy (occupancy.frag), push constants.
LIQUID_PUSH(OccupancyPush) {
  ivec3 grid_cells;        // the density grid
  int brick_cells;
  ivec3 bricks;            // the occupancy grid it writes
  // The atlas path (liquid/solver/grid_layout.h): tiles of the density atlas and of the occupancy atlas.
  int grid_columns;
  int grid_rows;
  int brick_columns;
  int brick_rows;
};

// The secondary particles as point sprites over the 3D view (whitewater_draw.vert/.frag), push
// constants; the output encoding is the raymarch's constant (LIQUID_RAYMARCH_OUTPUT_ID's value,
// at id 0 here).
LIQUID_PUSH(WhitewaterDrawPush) {
  mat4 view_projection;
  vec3 toward_camera;      // unit, world: a bubble is drawn this way by bubble_lift
  float bubble_lift;       // m: bubbles this far under the surface show through it
  float radius;            // m: a sprite's radius
  float focal_pixels;      // pixels per metre at clip w = 1
  float exposure;          // an HDR target's scale, as RenderSettings::exposure
  int texture_width;       // the secondary particles' texture, texels
};
#define LIQUID_WHITEWATER_DRAW_OUTPUT_ID 0

// Height field (height_field.vert/.frag), at LIQUID_BINDING_VIEW_UNIFORMS.
LIQUID_STRUCT(HeightFieldUniforms) {
  mat4 view_projection;
  vec3 camera_position;    // world, m
  float rest_depth;        // m
  vec3 sun_direction;      // towards the sun, unit
  float dry_threshold;     // m: water thinner than this is not drawn
  float vertical_scale;
  float skirt_base;        // m: where the side walls end below the bed
};

LIQUID_PUSH(HeightFieldPush) {
  int layer;  // LIQUID_HEIGHT_FIELD_GROUND or LIQUID_HEIGHT_FIELD_WATER
};

// 2D view (view2d.frag), push constants.
LIQUID_PUSH(View2dPush) {
  vec2 origin;             // framebuffer pixel of the domain's (0, 0) corner (its bottom left)
  float pixels_per_metre;  // domain scale on screen
  float iso_level;         // surface where rho / rho0 crosses this
  vec2 frame;              // framebuffer size, pixels
  float wall_pixels;       // tank wall thickness, pixels
  float depth_cells;       // how far (cells) the depth search looks up for the surface
};

// 2D particles (particles2d.vert/.frag), push constants.
LIQUID_PUSH(Particles2dPush) {
  vec2 origin;             // as View2dPush
  float pixels_per_metre;
  float point_size;        // pixels
  vec2 frame;              // framebuffer size, pixels
  int texture_width;       // particle texture width, texels
  float alpha;             // opacity of one point
};

#ifdef __cplusplus
}  // namespace liquid::gpu
#endif

#endif
