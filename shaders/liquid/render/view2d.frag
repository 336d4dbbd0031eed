#version 450
// 2D view of the liquid: the domain fitted into the frame (y up), the liquid where the bilinearly
// filtered rho / rho0 exceeds the iso level, with a one-pixel anti-aliased surface taken from the
// field's screen-space gradient; water darkens with depth below the surface and with compression,
// and has a light rim at the surface. Obstacles (the solver's analytic distances) are grey, and
// the tank's walls frame the domain on the left, right and bottom.
#extension GL_GOOGLE_include_directive : require
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

layout(set = 0, binding = LIQUID_BINDING_VIEW2D_DENSITY) uniform sampler2D u_density;  // rho / rho0, linear filtering
// Depth below the surface in cells, per cell (view2d_depth.frag), linear filtering.
layout(set = 0, binding = LIQUID_BINDING_VIEW2D_DEPTH) uniform sampler2D u_depth;

layout(push_constant) uniform View2dPushBlock {
  View2dPush pc;
};

// PANEL: the liquid and the obstacles alone, with their coverage in alpha, blended over a host's
// target (no background, letterbox or tank walls).
layout(constant_id = LIQUID_VIEW2D_PANEL_ID) const bool PANEL = false;

layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_color;

const vec3 k_letterbox = vec3(0.075, 0.085, 0.105);
const vec3 k_background = vec3(0.125, 0.140, 0.175);
const vec3 k_water_shallow = vec3(0.22, 0.56, 0.90);
const vec3 k_water_deep = vec3(0.03, 0.17, 0.48);
const vec3 k_water_rim = vec3(0.72, 0.90, 1.00);
const vec3 k_obstacle = vec3(0.50, 0.50, 0.52);
const vec3 k_obstacle_outline = vec3(0.30, 0.30, 0.32);
const vec3 k_wall = vec3(0.62, 0.66, 0.72);

float density_at(vec2 p) { return textureLod(u_density, p / u.domain.xy, 0.0).r; }

// Coverage of the region {d < 0} for a field d measured in pixels: a one-pixel linear ramp.
float coverage(float d_pixels) { return clamp(0.5 - d_pixels, 0.0, 1.0); }

// Signed distance (pixels, y up) to the tank: left, right and bottom walls of thickness
// wall_pixels just outside the domain, open at the top.
float tank_distance(vec2 q) {
  vec2 size = u.domain.xy * pc.pixels_per_metre;
  float t = pc.wall_pixels;
  float left = sd_box(vec3(q - vec2(-0.5 * t, 0.5 * (size.y - t)), 0.0), vec3(0.5 * t, 0.5 * (size.y + t), 1.0));
  float right = sd_box(vec3(q - vec2(size.x + 0.5 * t, 0.5 * (size.y - t)), 0.0), vec3(0.5 * t, 0.5 * (size.y + t), 1.0));
  float bottom = sd_box(vec3(q - vec2(0.5 * size.x, -0.5 * t), 0.0), vec3(0.5 * size.x + t, 0.5 * t, 1.0));
  return min(min(left, right), bottom);
}

// Signed distance (m) to obstacle i in the plane (a box: its rectangle, turned). A mesh's is its
// field's (MESH_FIELD=1, the scenes with meshes), sampled here in `meshes`.
float obstacle_distance_2d(int i, vec2 p, MeshSample meshes) { return obstacle_distance(i, vec3(p, 0.0), meshes); }

// Obstacle i over the pixel at p: solid grey with a darker outline.
void draw_obstacle(int i, vec2 p, MeshSample meshes, inout vec3 color, inout float alpha) {
  if (i >= obstacle_count()) return;
  float d_pixels = obstacle_distance_2d(i, p, meshes) * pc.pixels_per_metre;
  vec3 shade = mix(k_obstacle, k_obstacle_outline, smoothstep(-2.0, -1.0, d_pixels));
  color = mix(color, shade, coverage(d_pixels));
  alpha = mix(alpha, 1.0, coverage(d_pixels));
}

void main() {
  // Domain coordinates: q in pixels from the domain's bottom-left corner (y up), p in metres.
  vec2 q = vec2(gl_FragCoord.x - pc.origin.x, pc.origin.y - gl_FragCoord.y);
  vec2 p = q / pc.pixels_per_metre;
  vec2 domain = u.domain.xy;
  float h = cell_size();

  // Everything below that uses derivatives runs in uniform control flow.
  float rho = density_at(p);
  float f = rho - pc.iso_level;
  float f_gradient = length(vec2(dFdx(f), dFdy(f)));
  float f_pixels = f / max(f_gradient, 1e-6);  // signed pixels from the surface, > 0 inside

  // Half a pixel of softness at the domain's edge, where the liquid meets the walls.
  vec2 to_edge = min(q, domain * pc.pixels_per_metre - q);
  float in_domain = clamp(min(to_edge.x, to_edge.y) + 0.5, 0.0, 1.0);
  // `color` is premultiplied by `alpha`: each layer below goes over it with mix().
  vec3 color = PANEL ? vec3(0.0) : mix(k_letterbox, k_background, in_domain);
  float alpha = PANEL ? 0.0 : 1.0;

  float liquid = clamp(f_pixels + 0.5, 0.0, 1.0) * in_domain;
  if (liquid > 0.0) {
    // Depth below the surface, from the per-cell march of view2d_depth.frag.
    float depth = textureLod(u_depth, p / domain, 0.0).r;
    float deep = clamp(depth / pc.depth_cells, 0.0, 1.0);
    float compressed = clamp((rho - 1.0) * 2.0, 0.0, 1.0);  // rho above rho0: denser, darker
    vec3 water = mix(k_water_shallow, k_water_deep, clamp(0.85 * sqrt(deep) + 0.35 * compressed, 0.0, 1.0));
    // Light rim about half a cell (at least 1.5 pixels) wide just inside the surface.
    float rim_width = max(1.5, 0.6 * h * pc.pixels_per_metre);
    float rim = 1.0 - smoothstep(0.5 * rim_width, 1.5 * rim_width, f_pixels);
    water = mix(water, k_water_rim, 0.75 * rim);
    color = mix(color, water, liquid);
    alpha = mix(alpha, 1.0, liquid);
  }

  // Obstacles: solid grey with a darker outline, anti-aliased over one pixel of the distance.
  // The distance is metric near every surface (metaballs: a first-order estimate), so pixels are
  // metres times the scale; screen derivatives would break on the metaballs' field discontinuity.
  MeshSample meshes = mesh_sample(vec3(p, 0.0), false);
#define LIQUID_DRAW_OBSTACLE(i) draw_obstacle(i, p, meshes, color, alpha);
  FOR_EACH_OBSTACLE(LIQUID_DRAW_OBSTACLE)
#undef LIQUID_DRAW_OBSTACLE

  if (PANEL) {
    out_color = vec4(color / max(alpha, 1e-4), alpha);  // blended with SRC_ALPHA, 1 - SRC_ALPHA
    return;
  }
  color = mix(color, k_wall, coverage(tank_distance(q)));
  out_color = vec4(color, 1.0);
}
