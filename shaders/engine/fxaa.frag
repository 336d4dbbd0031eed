#version 450
// FXAA (Lottes, "FXAA 3.11", quality path): find the local contrast, the edge direction, walk
// along the edge to both ends, and blend across it by where this pixel sits on the edge, plus a
// sub-pixel term for thin features. Input is display-encoded colour; luma is computed from it.
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 out_color;
layout(set = 0, binding = 0) uniform sampler2D u_input;  // linear filtering, clamp to edge

layout(push_constant) uniform Push {
  vec2 inverse_size;          // 1 / resolution
  float edge_threshold;       // minimum relative contrast to process (0.125 = high quality)
  float edge_threshold_min;   // minimum absolute contrast (0.0312: skip dark noise)
  float subpixel_quality;     // 0 = off .. 1 = soft (0.75 default)
} pc;

const int k_search_steps = 12;
const float k_step_sizes[12] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
float luma_at(vec2 uv) { return luma(textureLod(u_input, uv, 0.0).rgb); }
float luma_offset(vec2 uv, ivec2 offset) { return luma_at(uv + vec2(offset) * pc.inverse_size); }

void main() {
  vec2 uv = v_uv;
  vec4 center_color = textureLod(u_input, uv, 0.0);
  float l_center = luma(center_color.rgb);
  float l_down = luma_offset(uv, ivec2(0, 1));
  float l_up = luma_offset(uv, ivec2(0, -1));
  float l_left = luma_offset(uv, ivec2(-1, 0));
  float l_right = luma_offset(uv, ivec2(1, 0));

  float l_min = min(l_center, min(min(l_down, l_up), min(l_left, l_right)));
  float l_max = max(l_center, max(max(l_down, l_up), max(l_left, l_right)));
  float range = l_max - l_min;
  if (range < max(pc.edge_threshold_min, l_max * pc.edge_threshold)) {
    out_color = center_color;
    return;
  }

  float l_down_left = luma_offset(uv, ivec2(-1, 1));
  float l_up_right = luma_offset(uv, ivec2(1, -1));
  float l_up_left = luma_offset(uv, ivec2(-1, -1));
  float l_down_right = luma_offset(uv, ivec2(1, 1));

  float l_down_up = l_down + l_up;
  float l_left_right = l_left + l_right;
  float l_left_corners = l_down_left + l_up_left;
  float l_down_corners = l_down_left + l_down_right;
  float l_right_corners = l_down_right + l_up_right;
  float l_up_corners = l_up_right + l_up_left;

  // Horizontal edge when the vertical second derivative dominates.
  float edge_h = abs(-2.0 * l_left + l_left_corners) + abs(-2.0 * l_center + l_down_up) * 2.0 +
                 abs(-2.0 * l_right + l_right_corners);
  float edge_v = abs(-2.0 * l_up + l_up_corners) + abs(-2.0 * l_center + l_left_right) * 2.0 +
                 abs(-2.0 * l_down + l_down_corners);
  bool horizontal = edge_h >= edge_v;

  float l_neg = horizontal ? l_up : l_left;     // the neighbour on the negative side
  float l_pos = horizontal ? l_down : l_right;  // and on the positive side
  float gradient_neg = abs(l_neg - l_center);
  float gradient_pos = abs(l_pos - l_center);
  bool neg_steeper = gradient_neg >= gradient_pos;
  float gradient_scaled = 0.25 * max(gradient_neg, gradient_pos);

  float step_length = horizontal ? pc.inverse_size.y : pc.inverse_size.x;
  float l_local_average;
  if (neg_steeper) {
    step_length = -step_length;
    l_local_average = 0.5 * (l_neg + l_center);
  } else {
    l_local_average = 0.5 * (l_pos + l_center);
  }

  // Start half a pixel across, on the edge itself.
  vec2 current = uv;
  if (horizontal) current.y += step_length * 0.5;
  else current.x += step_length * 0.5;
  vec2 offset = horizontal ? vec2(pc.inverse_size.x, 0.0) : vec2(0.0, pc.inverse_size.y);

  vec2 uv1 = current - offset * k_step_sizes[0];
  vec2 uv2 = current + offset * k_step_sizes[0];
  float l_end1 = luma_at(uv1) - l_local_average;
  float l_end2 = luma_at(uv2) - l_local_average;
  bool reached1 = abs(l_end1) >= gradient_scaled;
  bool reached2 = abs(l_end2) >= gradient_scaled;
  for (int i = 1; i < k_search_steps && !(reached1 && reached2); ++i) {
    if (!reached1) {
      uv1 -= offset * k_step_sizes[i];
      l_end1 = luma_at(uv1) - l_local_average;
      reached1 = abs(l_end1) >= gradient_scaled;
    }
    if (!reached2) {
      uv2 += offset * k_step_sizes[i];
      l_end2 = luma_at(uv2) - l_local_average;
      reached2 = abs(l_end2) >= gradient_scaled;
    }
  }

  float distance1 = horizontal ? (uv.x - uv1.x) : (uv.y - uv1.y);
  float distance2 = horizontal ? (uv2.x - uv.x) : (uv2.y - uv.y);
  bool nearer1 = distance1 < distance2;
  float distance_final = min(distance1, distance2);
  float edge_length = distance1 + distance2;
  float pixel_offset = -distance_final / edge_length + 0.5;

  // Only blend when the nearer end's luma variation agrees with the centre's side of the edge.
  bool center_smaller = l_center < l_local_average;
  bool correct_variation = ((nearer1 ? l_end1 : l_end2) < 0.0) != center_smaller;
  float final_offset = correct_variation ? pixel_offset : 0.0;

  // Sub-pixel aliasing: contrast of the 3x3 average against the centre.
  float l_average = (1.0 / 12.0) * (2.0 * (l_down_up + l_left_right) + l_left_corners + l_right_corners);
  float sub1 = clamp(abs(l_average - l_center) / range, 0.0, 1.0);
  float sub2 = (-2.0 * sub1 + 3.0) * sub1 * sub1;
  float sub_offset = sub2 * sub2 * pc.subpixel_quality;
  final_offset = max(final_offset, sub_offset);

  vec2 final_uv = uv;
  if (horizontal) final_uv.y += final_offset * step_length;
  else final_uv.x += final_offset * step_length;
  out_color = vec4(textureLod(u_input, final_uv, 0.0).rgb, center_color.a);
}
