#version 450
#extension GL_GOOGLE_include_directive : require
#include "liquid/render/view_blocks.h"
// Shallow-water view (section 6, figure 4), fragment stage: a lit sandy ground (darker where wet)
// and a semi-transparent water surface with a Fresnel reflection of the sky and a sun highlight,
// hidden where the water is thinner than the dry threshold.
layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform HeightFieldBlock {
  HeightFieldUniforms r;
};

layout(push_constant) uniform HeightFieldPushBlock {
  HeightFieldPush pc;
};

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in float v_depth;
layout(location = 3) in vec2 v_outward;
layout(location = 0) out vec4 out_color;

const vec3 k_sand = vec3(0.90, 0.76, 0.52);
const vec3 k_sky_horizon = vec3(0.78, 0.85, 0.92);
const vec3 k_sky_zenith = vec3(0.33, 0.55, 0.85);
const vec3 k_ambient = vec3(0.52, 0.50, 0.48);  // sky and bounce light, slightly warm
const vec3 k_water_shallow = vec3(0.16, 0.58, 0.78);
const vec3 k_water_deep = vec3(0.03, 0.22, 0.52);

vec3 sky(vec3 direction) { return mix(k_sky_horizon, k_sky_zenith, sqrt(clamp(direction.y, 0.0, 1.0))); }

void main() {
  // The inside of a side wall (seen across the plane) is not drawn: the walls are the outside of
  // the slab of ground and of the water column.
  vec3 view = normalize(r.camera_position - v_world);
  if (dot(vec3(v_outward.x, 0.0, v_outward.y), view) < 0.0) discard;
  vec3 n = normalize(v_normal);
  vec3 sun = normalize(r.sun_direction);
  float rest_depth = r.rest_depth, threshold = r.dry_threshold;

  if (pc.layer == LIQUID_HEIGHT_FIELD_GROUND) {
    // Wet sand under the water is darker; light: sun (Lambert) plus an ambient term.
    float wet = smoothstep(threshold, 2.0 * threshold, v_depth);
    vec3 albedo = k_sand * mix(1.0, 0.7, wet);
    float diffuse = max(dot(n, sun), 0.0);
    out_color = vec4(albedo * (k_ambient + 0.65 * diffuse), 1.0);
    return;
  }

  if (v_depth < threshold) discard;
  // Opacity of the column grows with its depth (Beer-Lambert-like); deeper water is darker.
  float thickness = 1.0 - exp(-v_depth / (1.5 * rest_depth));
  float cos_view = max(dot(n, view), 0.0);
  float fresnel = 0.02 + 0.98 * pow(1.0 - cos_view, 5.0);  // Schlick, water n = 1.33
  vec3 body = mix(k_water_shallow, k_water_deep, thickness) * (0.65 + 0.45 * max(dot(n, sun), 0.0));
  vec3 reflected = sky(reflect(-view, n));
  float specular = pow(max(dot(n, normalize(sun + view)), 0.0), 400.0) * 1.2;
  vec3 color = mix(body, reflected, fresnel) + specular * vec3(1.0, 0.97, 0.9);
  float alpha = clamp(mix(0.35, 0.9, thickness) + fresnel + specular, 0.0, 1.0);
  alpha *= smoothstep(threshold, 2.0 * threshold, v_depth);  // soft shoreline
  out_color = vec4(color, alpha);
}
