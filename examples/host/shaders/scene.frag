#version 450
// The host's shading: a checkered floor and a painted box, lit by one sun.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;
layout(location = 2) flat in int v_is_box;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 sun = normalize(vec3(0.4, 0.8, 0.45));
  float light = 0.35 + 0.65 * max(dot(normalize(v_normal), sun), 0.0);
  vec3 base;
  if (v_is_box == 1) {
    base = vec3(0.85, 0.35, 0.2);
  } else {
    ivec2 tile = ivec2(floor(v_world.xz / 0.1));
    base = ((tile.x + tile.y) & 1) == 0 ? vec3(0.75, 0.74, 0.7) : vec3(0.55, 0.56, 0.58);
  }
  vec3 color = base * light;
  out_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
