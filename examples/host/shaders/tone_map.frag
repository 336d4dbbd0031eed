#version 450
// The host's tone map, after the liquid: its HDR scene (linear radiance, the liquid's included) to
// the display image. ACES filmic curve (Narkowicz's fit), then the display's gamma: the display
// image is UNORM, so the encoding is done here.
layout(location = 0) in vec2 v_uv;
layout(set = 0, binding = 0) uniform sampler2D u_scene;
layout(push_constant) uniform ToneMapPush {
  ivec4 backdrop;  // x0, y0, x1, y1 pixels: a HUD panel's backdrop, darkened (empty: none)
} pc;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 x = textureLod(u_scene, v_uv, 0.0).rgb;
  vec3 mapped = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (all(greaterThanEqual(pixel, pc.backdrop.xy)) && all(lessThan(pixel, pc.backdrop.zw))) mapped *= 0.3;
  out_color = vec4(pow(mapped, vec3(1.0 / 2.2)), 1.0);
}
