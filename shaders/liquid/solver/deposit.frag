#version 450
// Separable splat, deposit stage, fragment shader: the particle's bilinear weight w at this cell's
// centre, written as (w u, w) and summed by additive blending like splat.frag. In 3D it writes the
// lower slice's share (1 - f) to target 0 and the upper slice's f to target 1 (deposit.vert). The
// clamp to the outermost cell centres (deposit.vert) keeps the footprint inside the grid, and inside
// its slice's tile on the atlas path (a pixel of the next tile is at least one cell away and gets
// weight 0).
layout(location = 0) flat in vec4 v_point;  // xy the particle (pixels), z the upper slice's share
layout(location = 1) flat in vec3 v_velocity;
layout(location = 0) out vec4 out_splat;
#if DIM == 3
layout(location = 1) out vec4 out_upper_slice;
#endif

void main() {
  vec2 d = max(1.0 - abs(gl_FragCoord.xy - v_point.xy), 0.0);
  vec4 splat = d.x * d.y * vec4(v_velocity, 1.0);
#if DIM == 3
  out_splat = (1.0 - v_point.z) * splat;
  out_upper_slice = v_point.z * splat;
#else
  out_splat = splat;
#endif
}
