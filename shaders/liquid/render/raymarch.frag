#version 450
// Raymarch of the density volume (section 7, figure 3): the liquid surface is where rho / rho0
// crosses the iso level. Rays cross empty bricks of the occupancy volume in one step each, march
// occupied bricks in sub-cell steps, refine the crossing by bisection, and take the normal from the
// density gradient. Shading: Fresnel reflection of a sky, refraction onto the floor tinted by
// Beer-Lambert absorption over the liquid's thickness, and a sun highlight. Obstacles (the solver's
// analytic shapes), a tiled floor and the tank's frame (the domain box's edges) are ray traced in the
// same pass. Writes colour and depth.
#extension GL_GOOGLE_include_directive : require
#define DIM 3
#include "liquid/common.glsl"
#include "liquid/render/view_blocks.h"

#include "liquid/render/raymarch_march.glsl"
#include "liquid/render/raymarch_tiles.glsl"

layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_COARSE) uniform sampler2D u_coarse;  // the coarse rays' crossings, nearest
// How far before the coarse rays' nearest crossing a pixel's march begins, in cells: the surface
// between coarse rays a pixel or two apart lies well within it.
const float k_start_margin_cells = 1.0;

// Composited into a host's frame (LiquidRenderer with HostTargets): no floor, sky or tank of our
// own; the liquid is blended over the host's colour with its coverage in alpha, and pixels that
// show no liquid are left to the host.
layout(constant_id = LIQUID_RAYMARCH_COMPOSITE_ID) const bool COMPOSITE = false;
layout(constant_id = LIQUID_RAYMARCH_OUTPUT_ID) const int OUTPUT_ENCODING = LIQUID_OUTPUT_DISPLAY;
// For the screen tiles around which no coarse ray met the liquid (raymarch_tiles.frag): the march
// and the liquid's shading are left out, not merely skipped (lavapipe runs both sides of every
// branch). raymarch_tile.vert draws the tiles of this pipeline's kind.
layout(constant_id = LIQUID_RAYMARCH_BACKGROUND_ONLY_ID) const bool BACKGROUND_ONLY = false;

#if TRANSMIT
// Compositing with dual-source blending (BlendMode::Transmit): the host's colour behind is
// multiplied by out_transmit per channel, so the liquid's absorption tints what shows through.
layout(location = 0, index = 0) out vec4 out_color;
layout(location = 0, index = 1) out vec4 out_transmit;
#else
layout(location = 0) out vec4 out_color;
#endif

const vec3 k_absorption = vec3(6.0, 1.6, 0.9);  // 1/m: red is absorbed first, so depth reads blue-green

vec3 sky(vec3 dir) {
  float up = clamp(dir.y * 0.5 + 0.5, 0.0, 1.0);
  vec3 color = mix(vec3(0.78, 0.80, 0.82), vec3(0.30, 0.52, 0.85), pow(up, 0.8));
  float sun = max(dot(dir, r.sun_direction), 0.0);
  return color + vec3(1.0, 0.95, 0.85) * (pow(sun, 400.0) * 6.0 + pow(sun, 12.0) * 0.15);
}

// Tiled floor at y = 0, darker inside the tank's footprint.
vec3 floor_color(vec3 p) {
  vec2 tile = floor(p.xz / 0.1);
  float checker = mod(tile.x + tile.y, 2.0);
  vec3 color = mix(vec3(0.55, 0.53, 0.50), vec3(0.68, 0.66, 0.62), checker);
  bool inside = all(greaterThanEqual(p.xz, vec2(0.0))) && all(lessThanEqual(p.xz, u.domain.xz));
  if (inside) color *= vec3(0.82, 0.86, 0.9);
  float fade = exp(-0.15 * length(p.xz - 0.5 * u.domain.xz));
  return mix(vec3(0.7, 0.72, 0.75), color, fade) * (0.55 + 0.45 * max(r.sun_direction.y, 0.0));
}

// The normal of obstacle `index` at p. With the obstacle's index the unrolled loop's, as in
// trace_obstacles(): its kind is then a constant and only its shape's code is compiled. With the
// run-time index every shape's code, the metaballs' loop included, was inlined into each of the six
// distances of the central differences, which LLVM 15 took many minutes to compile for two bodies.
// Written as a loop, not with literal indices (FOR_EACH_OBSTACLE), with which lavapipe's memory grew
// by 3 MiB a frame (tests/gpu/test_liquid_resources.cpp), as it did when the bisection's count was a
// uniform: a loop bounded by a uniform it can read at a constant index (the metaballs' count) seems
// to be compiled again whenever the uniform buffer is rebound.
vec3 obstacle_normal_of(int index, vec3 p) {
  vec3 n = vec3(0.0, 1.0, 0.0);
  [[unroll]] for (int i = 0; i < obstacle_count(); ++i)
    if (i == index) n = obstacle_normal(i, p);
  return n;
}

// What a ray sees when it does not hit the liquid: an obstacle, the floor or the sky. Written as
// selects with one sky lookup (the obstacle's reflection of the sky or the sky itself), not as a
// branch per surface: lavapipe runs every branch's code for every pixel, and each sky costs three
// powers.
vec3 background(vec3 origin, vec3 dir, out float depth_t) {
  int obstacle;
  float t_obstacle = trace_obstacles(origin, dir, obstacle);
  float t_floor = dir.y < -1e-5 ? -origin.y / dir.y : k_no_hit;
  bool on_obstacle = t_obstacle < t_floor && t_obstacle < k_no_hit;
  bool on_floor = !on_obstacle && t_floor < k_no_hit;
  depth_t = on_obstacle ? t_obstacle : t_floor;  // k_no_hit where the ray meets neither
  vec3 p = origin + dir * (on_obstacle || on_floor ? depth_t : 0.0);
  vec3 n = obstacle_normal_of(obstacle, p);
  vec3 sky_seen = sky(on_obstacle ? reflect(dir, n) : dir);
  if (on_obstacle) {
    vec3 l = r.sun_direction;
    float diffuse = max(dot(n, l), 0.0);
    float spec = pow(max(dot(n, normalize(l - dir)), 0.0), 48.0);
    vec3 base = vec3(0.62, 0.6, 0.58);
    return base * (0.25 + 0.75 * diffuse) + vec3(0.35) * spec + 0.08 * sky_seen;
  }
  return on_floor ? floor_color(p) : sky_seen;
}

// Where the ray enters the tank already inside the liquid, the surface seen is the tank's wall
// (its glass): the normal is that face's, not the density's gradient, which runs along the wall
// there and lit it as a grazing reflection (white streaks where liquid meets a wall).
vec3 box_face_normal(vec3 p) {
  vec3 to_low = p, to_high = u.domain - p;
  vec3 distance = min(to_low, to_high);
  int a = distance.x < distance.y ? (distance.x < distance.z ? 0 : 2) : (distance.y < distance.z ? 1 : 2);
  vec3 n = vec3(0.0);
  n[a] = to_low[a] < to_high[a] ? -1.0 : 1.0;
  return n;
}

// Only where `wanted`, with that in the loop's condition (as the bisection's): a group of pixels
// that wants none makes one trip of two lookups instead of six.
vec3 density_normal(vec3 p, bool wanted) {
  vec3 g = vec3(0.0);
  [[dont_unroll]] for (int a = 0; a < 3 && wanted; ++a) {
    vec3 e = vec3(0.0);
    e[a] = cell_size();
    g[a] = density_at(p + e) - density_at(p - e);
  }
  float len = length(g);
  return len > 1e-6 ? -g / len : vec3(0.0, 1.0, 0.0);
}

// Where this pixel's march begins. The coarse pass marched the rays around it (raymarch_coarse.frag):
// just before the nearest crossing the four of them found, the surface between them lying near
// theirs; past the span's end when none of them found one. Where that point already lies inside
// the liquid (a surface nearer than the coarse rays saw), the whole span.
float march_start(vec2 pixel, vec2 along, vec3 origin, vec3 dir) {
  ivec2 a = clamp(coarse_ray_before(ivec2(pixel)), ivec2(0), ivec2(r.coarse_width, r.coarse_height) - 2);
  float nearest = min(min(texelFetch(u_coarse, a, 0).r, texelFetch(u_coarse, a + ivec2(1, 0), 0).r),
                      min(texelFetch(u_coarse, a + ivec2(0, 1), 0).r, texelFetch(u_coarse, a + ivec2(1, 1), 0).r));
  float start = clamp(nearest - k_start_margin_cells * cell_size(), along.x, along.y);
  bool inside = density_at(origin + dir * start) > r.iso_level;
  return nearest >= k_no_hit ? along.y + cell_size() : (inside ? along.x : start);
}

void main() {
  vec2 pixel = gl_FragCoord.xy - vec2(r.viewport_x, r.viewport_y);  // in the view, at the pixel's centre
  vec3 origin, dir;
  view_ray(pixel / vec2(r.viewport_width, r.viewport_height), origin, dir);
  vec2 span = intersect_box(origin, 1.0 / dir, vec3(0.0), u.domain);
  float t_liquid = k_no_hit;
  if (!BACKGROUND_ONLY && span.x <= span.y && span.y > 0.0) {
    vec2 along = liquid_span(origin, dir, span);
    t_liquid = march_liquid(origin, dir, march_start(pixel, along, origin, dir), along.y);
  }

  // What lies behind the liquid is traced along the refracted ray, or along the view ray where there
  // is no liquid: one trace either way (lavapipe would run two).
  vec3 behind_origin = origin, behind_dir = dir;
  vec3 reflected = vec3(0.0), scattered = vec3(0.0);
  float fresnel = 0.0, thickness = 0.0, spec = 0.0;
  if (t_liquid < k_no_hit) {
    vec3 p = origin + dir * t_liquid;
    bool through_wall = span.x > 0.0 && t_liquid <= span.x + 1e-3 * cell_size();
    vec3 n = through_wall ? box_face_normal(p) : density_normal(p, t_liquid < k_no_hit && !through_wall);
    float cos_theta = clamp(dot(-dir, n), 0.0, 1.0);
    fresnel = 0.02 + 0.98 * pow(1.0 - cos_theta, 5.0);  // Schlick, water F0 = 0.02
    reflected = sky(reflect(dir, n));
    // Refraction: thickness along the refracted ray (a few coarse steps), then what lies behind.
    // Each step asks the nearest cell, not a trilinear lookup (eight texels): the loop runs to
    // the slowest ray of each group of pixels, and a coarse count needs no more.
    vec3 refracted_dir = refract(dir, n, 1.0 / 1.33);
    if (dot(refracted_dir, refracted_dir) < 1e-6) refracted_dir = dir;
    float step_length = 2.0 * cell_size();
    // Each pixel starts its count at its own fraction of a step (interleaved gradient noise):
    // the nearest-cell samples of neighbouring pixels would otherwise cross the cell layers
    // together and band a face seen straight on (the tank's glass).
    float jitter = fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
    vec3 q = p + refracted_dir * step_length * (jitter - 1.0);
    // Kept a loop, [[dont_unroll]] (docs/lavapipe-performance.md): it ends when every ray of the
    // group has left the box.
    [[dont_unroll]] for (int k = 0; k < 16; ++k) {
      q += refracted_dir * step_length;
      if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, u.domain))) break;
      if (fetch_grid(u_density, ivec3(q / cell_size())).r > r.iso_level) thickness += step_length;
    }
    spec = pow(max(dot(n, normalize(r.sun_direction - dir)), 0.0), 180.0);
    scattered = vec3(0.01, 0.05, 0.08) * (1.0 - exp(-2.0 * thickness));
    if (COMPOSITE) {
      // What shows through is the host's colour behind (blending): it is filtered by the
      // transmittance, per channel with dual-source blending, else by its mean; the rest is
      // reflection, scattering and highlight.
      vec3 through_rgb = (1.0 - fresnel) * exp(-k_absorption * (thickness + 0.02));
      float through = dot(through_rgb, vec3(1.0 / 3.0));
      vec3 own = fresnel * reflected + (1.0 - fresnel) * scattered + vec3(1.0, 0.97, 0.9) * spec * 1.5;
      float coverage = 1.0 - through;
      gl_FragDepth = clip_depth(p);
      // Blended as src * coverage + dst * (1 - coverage), so the colour is own / coverage.
      if (OUTPUT_ENCODING == LIQUID_OUTPUT_HDR) {
        out_color = vec4(own * r.exposure / max(coverage, 1e-3), coverage);  // linear radiance
      } else {
        own = own / (1.0 + 0.15 * own);  // a soft shoulder into [0, 1]
        vec3 linear = clamp(own / max(coverage, 1e-3), 0.0, 1.0);
        out_color = vec4(OUTPUT_ENCODING == LIQUID_OUTPUT_LINEAR ? linear : pow(linear, vec3(1.0 / 2.2)), coverage);
      }
#if TRANSMIT
      // src + src1 * dst: the same light of its own (premultiplied here), the host's colour
      // filtered channel by channel.
      out_color.rgb *= coverage;
      out_transmit = vec4(through_rgb, 0.0);
#endif
      return;
    }
    behind_origin = p + refracted_dir * 1e-3;
    behind_dir = refracted_dir;
  } else if (COMPOSITE) {
    discard;
  }
  float depth_t;
  vec3 color = background(behind_origin, behind_dir, depth_t);
  if (t_liquid < k_no_hit) {
    vec3 transmitted = color * exp(-k_absorption * (thickness + 0.02)) + scattered;
    color = mix(transmitted, reflected, fresnel) + vec3(1.0, 0.97, 0.9) * spec * 1.5;
    depth_t = t_liquid;
  }

  gl_FragDepth = depth_t < k_no_hit ? clip_depth(origin + dir * depth_t) : 1.0;
  out_color = vec4(display_encoded(color), 1.0);
}
