// The tank's frame: the 12 edges of the domain box as thin bars, so the walls the liquid rests
// against are visible. Drawn over the raymarched frame by tank_frame.vert and .frag (not when the
// liquid is composited into a host's frame).
#ifndef LIQUID_TANK_FRAME_GLSL
#define LIQUID_TANK_FRAME_GLSL

// The bars' radius, m: a fraction of the domain's largest side.
float tank_frame_radius() { return 0.004 * max(max(u.domain.x, u.domain.y), u.domain.z); }

vec3 tank_frame_color() { return vec3(0.16, 0.17, 0.19) * (0.6 + 0.4 * max(r.sun_direction.y, 0.0)); }

// Edge `index` (0 to LIQUID_TANK_FRAME_BARS - 1) as a corner and the vector along it: the edges along axis index / 4, at the
// corner of the other two axes that the two bits of index % 4 pick.
void tank_edge(int index, out vec3 corner, out vec3 along) {
  int axis = index / 4, bits = index % 4;
  int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
  corner = vec3(0.0);
  corner[u_axis] = (bits & 1) != 0 ? u.domain[u_axis] : 0.0;
  corner[v_axis] = (bits & 2) != 0 ? u.domain[v_axis] : 0.0;
  along = vec3(0.0);
  along[axis] = u.domain[axis];
}

#endif
