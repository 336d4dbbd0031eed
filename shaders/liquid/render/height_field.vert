#version 450
// Shallow-water view (section 6, figure 4), vertex stage: one vertex per grid cell, generated from
// gl_VertexIndex (vertex (x, y) of the grid with its edge ring is index y (n.x + 2) + x; an index
// buffer makes the triangles), on the horizontal plane (scene x -> world x,
// scene y -> world z, up = world y). Layer 0 is the ground b(x, y); layer 1 the water surface
// b + h with h = rest_depth * rho / rho0. An extra ring of vertices on the domain's edge drops to
// a base height (ground) or to the ground (water), so both meshes get side walls.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform HeightFieldBlock {
  HeightFieldUniforms r;
};
layout(set = 0, binding = LIQUID_BINDING_HEIGHT_FIELD_DENSITY) uniform sampler2D u_density;  // rho / rho0, linear filtering

layout(push_constant) uniform HeightFieldPushBlock {
  HeightFieldPush pc;
};

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out float v_depth;  // water depth h (m)
layout(location = 3) out vec2 v_outward;  // side walls: outward direction (x, z); 0 on the top

// h at cell c (clamped to the grid), m. The lookup is at the texel centre: exactly the cell.
float water_depth(ivec2 c) {
  ivec2 n = grid_cells().xy;
  c = clamp(c, ivec2(0), n - 1);
  return r.rest_depth * textureLod(u_density, (vec2(c) + 0.5) / vec2(n), 0.0).r;
}

// Height of this layer's surface over cell c, m: b, or b + h for the water.
float surface(ivec2 c) {
  c = clamp(c, ivec2(0), grid_cells().xy - 1);
  float b = ground_height(cell_center(ivec3(c, 0)).xy);
  return pc.layer == LIQUID_HEIGHT_FIELD_WATER ? b + water_depth(c) : b;
}

void main() {
  ivec2 n = grid_cells().xy;
  float h = cell_size();
  float scale = r.vertical_scale;
  // Vertex g in [0, n + 1]^2: g - 1 is the cell, 0 and n + 1 are the edge ring.
  ivec2 g = ivec2(gl_VertexIndex % (n.x + 2), gl_VertexIndex / (n.x + 2));
  ivec2 c = clamp(g - 1, ivec2(0), n - 1);
  vec2 xy = clamp((vec2(g) - 0.5) * h, vec2(0.0), u.domain.xy);
  bool edge = any(equal(g, ivec2(0))) || any(equal(g, n + 1));

  v_depth = water_depth(c);
  float height;
  vec3 normal;
  if (edge) {
    // Side wall: the ground drops to the base, the water to the ground.
    height = pc.layer == LIQUID_HEIGHT_FIELD_WATER ? ground_height(xy) : r.skirt_base;
    vec2 outward = vec2(g.x == 0 ? -1.0 : (g.x == n.x + 1 ? 1.0 : 0.0), g.y == 0 ? -1.0 : (g.y == n.y + 1 ? 1.0 : 0.0));
    normal = normalize(vec3(outward.x, 0.0, outward.y));
    v_outward = outward;
  } else {
    height = surface(c);
    // Central differences of the surface (one-sided at the edges through the clamp).
    float dx = (surface(c + ivec2(1, 0)) - surface(c - ivec2(1, 0))) / (2.0 * h);
    float dy = (surface(c + ivec2(0, 1)) - surface(c - ivec2(0, 1))) / (2.0 * h);
    normal = normalize(vec3(-scale * dx, 1.0, -scale * dy));
    v_outward = vec2(0.0);
  }
  v_world = vec3(xy.x, scale * height, xy.y);
  v_normal = normal;
  gl_Position = r.view_projection * vec4(v_world, 1.0);
}
