#version 450
// Separable splat, deposit stage, fragment shader: the particle's bilinear weight at this cell's
// centre times its slice's weight (trilinear in 3D), written as (w u, w) and summed by additive
// blending like splat.frag. The clamp to the outermost cell centres (deposit.vert) keeps the
// footprint inside the grid, and inside its slice's tile on the atlas path (a pixel of the next
// tile is at least one cell away and gets weight 0).
layout(location = 0) flat in vec4 v_point;  // xy the particle (pixels), z the slice's weight
layout(location = 1) flat in vec3 v_velocity;
layout(location = 0) out vec4 out_splat;

void main() {
  vec2 d = max(1.0 - abs(gl_FragCoord.xy - v_point.xy), 0.0);
  float w = d.x * d.y * v_point.z;
  out_splat = vec4(w * v_velocity, w);
}
