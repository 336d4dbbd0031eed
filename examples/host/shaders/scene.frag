#version 450
// The host's shading in linear radiance (its HDR target; the tone map comes after the liquid): a
// checkered floor and a painted paddle, lit by one sun and the sky.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;
layout(location = 2) flat in int v_material;  // host_mesh.h: 0 checkered floor, 1 paint
layout(location = 0) out vec4 out_color;

void main() {
  vec3 sun = normalize(vec3(0.4, 0.8, 0.45));
  vec3 light = vec3(1.3, 1.22, 1.1) * max(dot(normalize(v_normal), sun), 0.0) + vec3(0.2, 0.24, 0.3);
  vec3 base;
  if (v_material == 1) {
    base = vec3(0.7, 0.18, 0.07);
  } else {
    ivec2 tile = ivec2(floor(v_world.xz / 0.25));
    base = ((tile.x + tile.y) & 1) == 0 ? vec3(0.42, 0.40, 0.36) : vec3(0.2, 0.21, 0.23);
  }
  out_color = vec4(base * light, 1.0);
}
