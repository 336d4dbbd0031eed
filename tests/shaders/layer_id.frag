#version 450
// Writes (x, y, layer, 1) so a test can check that layered rendering reached every slice.
layout(location = 0) in vec2 v_uv;
layout(location = 1) flat in int v_layer;
layout(location = 0) out vec4 out_value;

void main() { out_value = vec4(floor(gl_FragCoord.xy), float(v_layer), 1.0); }
