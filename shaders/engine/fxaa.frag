#version 450
// FXAA (Lottes, "FXAA 3.11", quality path): find the local contrast, the edge direction, walk
// along the edge to both ends, and blend across it by where this pixel sits on the edge, plus a
// sub-pixel term for thin features. Input is display-encoded colour; luma is computed from it.
//
// Written for lavapipe, where every texture read runs for every pixel, on both sides of the
// contrast test (docs/lavapipe-performance.md), so the win is fewer reads:
// - The 3x3 neighbourhood costs four single-texel reads per pixel, not nine filtered ones. A 2x2
//   quad of pixels needs the 4x4 texels around it: each pixel reads its own and the three on its
//   outer side, and takes the others from its quad neighbours through fine derivatives (the
//   neighbour's value is v -+ dFdxFine(v)); llvmpipe computes derivatives per quad, as a GPU does.
// - The edge search's first step comes from the neighbourhood, and the rest is a loop kept rolled,
//   so a group of pixels with no edge runs one trip of two reads instead of all twelve unrolled.
// - The final blend mixes the centre with the neighbour across the edge, both texels at hand,
//   instead of a filtered read between them.
#extension GL_EXT_control_flow_attributes : require
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

// A single texel, clamped to the edge as the sampler is.
vec3 texel(ivec2 p, ivec2 last) { return texelFetch(u_input, clamp(p, ivec2(0), last), 0).rgb; }

// The value v of this pixel's neighbour across the quad: horizontally (side.x: -1 for the left
// pixel of its quad, +1 for the right one, so the neighbour is at -side.x), vertically, diagonally.
float across_x(float v, ivec2 side) { return v - float(side.x) * dFdxFine(v); }
float across_y(float v, ivec2 side) { return v - float(side.y) * dFdyFine(v); }
vec3 across_x(vec3 v, ivec2 side) { return v - float(side.x) * dFdxFine(v); }
vec3 across_y(vec3 v, ivec2 side) { return v - float(side.y) * dFdyFine(v); }

void main() {
  vec2 uv = v_uv;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(u_input, 0) - 1;
  vec4 center_color = texelFetch(u_input, pixel, 0);
  float l_center = luma(center_color.rgb);

  // The 3x3 neighbourhood, in offsets along `side`, the outer side of this pixel in its quad.
  ivec2 side = 2 * (pixel & 1) - 1;
  vec3 outer_x_color = texel(pixel + ivec2(side.x, 0), last);   // read here
  vec3 outer_y_color = texel(pixel + ivec2(0, side.y), last);
  float outer_x = luma(outer_x_color);
  float outer_y = luma(outer_y_color);
  float outer_xy = luma(texel(pixel + side, last));
  // The quad neighbours' centres (their colours serve the final blend too) and what they read on
  // their outer sides. Derivatives only here, in uniform control flow, before the contrast test.
  vec3 inner_x_color = across_x(center_color.rgb, side);
  vec3 inner_y_color = across_y(center_color.rgb, side);
  float inner_x = luma(inner_x_color);
  float inner_y = luma(inner_y_color);
  float inner_xy = across_x(inner_y, side);
  float inner_x_outer_y = across_x(outer_y, side);
  float outer_x_inner_y = across_y(outer_x, side);
  bool left_outer = side.x < 0, up_outer = side.y < 0;
  float l_left = left_outer ? outer_x : inner_x;
  float l_right = left_outer ? inner_x : outer_x;
  float l_up = up_outer ? outer_y : inner_y;
  float l_down = up_outer ? inner_y : outer_y;
  float l_up_left = left_outer ? (up_outer ? outer_xy : outer_x_inner_y) : (up_outer ? inner_x_outer_y : inner_xy);
  float l_up_right = left_outer ? (up_outer ? inner_x_outer_y : inner_xy) : (up_outer ? outer_xy : outer_x_inner_y);
  float l_down_left = left_outer ? (up_outer ? outer_x_inner_y : outer_xy) : (up_outer ? inner_xy : inner_x_outer_y);
  float l_down_right = left_outer ? (up_outer ? inner_xy : inner_x_outer_y) : (up_outer ? outer_x_inner_y : outer_xy);

  float l_min = min(l_center, min(min(l_down, l_up), min(l_left, l_right)));
  float l_max = max(l_center, max(max(l_down, l_up), max(l_left, l_right)));
  float range = l_max - l_min;
  bool edge = range >= max(pc.edge_threshold_min, l_max * pc.edge_threshold);
#if MARK
  // The first of the two passes: every pixel keeps its own colour, and the depth marks the quads
  // that hold an edge (1) or none (0). The second pass (this shader without MARK) draws at depth 0
  // with the test LESS, so the early depth test drops the rest before the search runs: lavapipe
  // skips a 4x4 block whose pixels all fail it. Whole quads are marked, so the second pass's quad
  // derivatives always have their four pixels.
  float edge_mark = edge ? 1.0 : 0.0;
  float edge_mark_y = across_y(edge_mark, side);
  out_color = center_color;
  gl_FragDepth = max(max(edge_mark, across_x(edge_mark, side)), max(edge_mark_y, across_x(edge_mark_y, side)));
  return;
#endif
  if (!edge) {
    out_color = center_color;
    return;
  }

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

  // The first step each way lies between two texels of the 3x3 neighbourhood: no read needed.
  float l_across_neg = horizontal ? (neg_steeper ? l_up_left : l_down_left) : (neg_steeper ? l_up_left : l_up_right);
  float l_across_pos = horizontal ? (neg_steeper ? l_up_right : l_down_right) : (neg_steeper ? l_down_left : l_down_right);
  float l_along_neg = horizontal ? l_left : l_up;
  float l_along_pos = horizontal ? l_right : l_down;
  vec2 uv1 = current - offset * k_step_sizes[0];
  vec2 uv2 = current + offset * k_step_sizes[0];
  float l_end1 = 0.5 * (l_along_neg + l_across_neg) - l_local_average;
  float l_end2 = 0.5 * (l_along_pos + l_across_pos) - l_local_average;
  bool reached1 = abs(l_end1) >= gradient_scaled;
  bool reached2 = abs(l_end2) >= gradient_scaled;
  [[dont_unroll]] for (int i = 1; i < k_search_steps && !(reached1 && reached2); ++i) {
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

  // The filtered lookup final_offset (at most 1) of a pixel towards the steeper neighbour, as a
  // blend of the two texels: that neighbour's colour comes from this pixel's reads or its quad's.
  bool toward_outer = horizontal ? ((side.y < 0) == neg_steeper) : ((side.x < 0) == neg_steeper);
  vec3 across_color = horizontal ? (toward_outer ? outer_y_color : inner_y_color)
                                 : (toward_outer ? outer_x_color : inner_x_color);
  out_color = vec4(mix(center_color.rgb, across_color, final_offset), center_color.a);
}
