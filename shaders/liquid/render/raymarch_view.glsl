// The raymarch's view (RaymarchUniforms of view_blocks.h): the ray through a point of the view, the
// depth a point is written at, and the display encoding of a colour. Shared by the raymarch's passes
// and the tank's frame (tank_frame.frag).
#ifndef LIQUID_RAYMARCH_VIEW_GLSL
#define LIQUID_RAYMARCH_VIEW_GLSL

layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform RaymarchBlock {
  RaymarchUniforms r;
};

// The ray through the view at `uv` (0 at the viewport's top-left corner, 1 at its bottom-right),
// from the near plane, for any projection: perspective or orthographic, forward or reversed Z, a
// finite or an infinite far plane (the second point is halfway in clip depth, finite for all of
// them).
void view_ray(vec2 uv, out vec3 origin, out vec3 dir) {
  vec2 ndc = uv * 2.0 - 1.0;
  vec4 near_point = r.inverse_view_projection * vec4(ndc, r.near_depth, 1.0);
  vec4 mid_point = r.inverse_view_projection * vec4(ndc, 0.5, 1.0);
  origin = near_point.xyz / near_point.w;
  dir = normalize(mid_point.xyz / mid_point.w - origin);
}

// The depth the target stores for a point seen.
float clip_depth(vec3 p) {
  vec4 clip = r.view_projection * vec4(p, 1.0);
  return clamp(clip.z / clip.w, 0.0, 1.0);
}

// Filmic-ish tone curve and display encoding (the targets are UNORM, written as sRGB values).
vec3 display_encoded(vec3 color) {
  color = color / (1.0 + 0.15 * color);
  return pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2));
}

#endif
