#version 450
// The liquid renderer's frame (RGBA8) into the swapchain image, pixel for pixel: the attachment's
// format (B8G8R8A8 on lavapipe) takes care of the channel order. The window is opaque.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_color;
layout(set = 0, binding = 0) uniform sampler2D u_frame;

void main() {
  out_color = vec4(texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb, 1.0);
}
