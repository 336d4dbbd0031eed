#version 450
// The 3D view's mesh obstacles: the raymarch's obstacle shading without its sky reflection
// (raymarch.frag's shade_obstacle), display-encoded as the raymarch writes its frame.
#extension GL_GOOGLE_include_directive : require
#include "liquid/shared.h"

layout(push_constant) uniform Push {
  MeshDrawPush pc;
};
layout(location = 0) flat in vec3 v_normal;
layout(location = 0) out vec4 out_color;

void main() {
  float diffuse = max(dot(v_normal, pc.sun_direction.xyz), 0.0);
  vec3 base = vec3(0.62, 0.6, 0.58);
  vec3 color = base * (0.25 + 0.75 * diffuse);
  out_color = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
