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

layout(std140, set = 0, binding = LIQUID_BINDING_VIEW_UNIFORMS) uniform RaymarchBlock {
  RaymarchUniforms r;
};
// Both grids are 3D images, or 2D atlases of their slices on the atlas path (ATLAS=1, liquid/solver/grid_layout.h).
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_DENSITY) uniform GRID_SAMPLER u_density;    // rho / rho0, linear filtering
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_OCCUPANCY) uniform GRID_SAMPLER u_occupancy;  // per-brick max, nearest

// Composited into a host's frame (LiquidRenderer with HostTargets): no floor, sky or tank of our
// own; the liquid is blended over the host's colour with its coverage in alpha, and pixels that
// show no liquid are left to the host.
layout(constant_id = LIQUID_RAYMARCH_COMPOSITE_ID) const bool COMPOSITE = false;
layout(constant_id = LIQUID_RAYMARCH_OUTPUT_ID) const int OUTPUT_ENCODING = LIQUID_OUTPUT_DISPLAY;
// For the pixels outside the domain box's screen rectangle (raymarch.cpp): their rays cannot reach
// the liquid, so the march and the liquid's shading are left out, not merely skipped (lavapipe runs
// both sides of every branch).
layout(constant_id = LIQUID_RAYMARCH_BACKGROUND_ONLY_ID) const bool BACKGROUND_ONLY = false;

layout(location = 0) in vec2 v_uv;
#if TRANSMIT
// Compositing with dual-source blending (BlendMode::Transmit): the host's colour behind is
// multiplied by out_transmit per channel, so the liquid's absorption tints what shows through.
layout(location = 0, index = 0) out vec4 out_color;
layout(location = 0, index = 1) out vec4 out_transmit;
#else
layout(location = 0) out vec4 out_color;
#endif

const float k_no_hit = 1e30;
// Refinements of a crossing. A constant, not a uniform: lavapipe (Mesa 22.3) compiles a fresh copy
// of a shader whose loop count is read from a uniform block on every draw and keeps every copy
// (2.7 MB per frame of this shader; docs/memory.md).
const int k_bisection_steps = 5;
// A bound on the march's trips (an empty brick or a fine step each), far above what a ray through
// the largest grid needs; the loop ends on t_exit first.
const int k_max_march_trips = 4096;
const vec3 k_absorption = vec3(6.0, 1.6, 0.9);  // 1/m: red is absorbed first, so depth reads blue-green

float density_at(vec3 p) {
#if ATLAS
  return atlas_sample_linear(u_density, p / u.domain, u.grid_cells, atlas_tiles()).r;
#else
  return textureLod(u_density, p / u.domain, 0.0).r;
#endif
}

// The largest density of a brick (occupancy.frag).
float brick_max_density(ivec3 brick) {
#if ATLAS
  return texelFetch(u_occupancy, atlas_texel(brick, r.bricks, ivec2(r.brick_columns, r.brick_rows)), 0).r;
#else
  return texelFetch(u_occupancy, brick, 0).r;
#endif
}

vec2 intersect_box(vec3 origin, vec3 inv_dir, vec3 lo, vec3 hi) {
  vec3 t0 = (lo - origin) * inv_dir, t1 = (hi - origin) * inv_dir;
  vec3 tmin = min(t0, t1), tmax = max(t0, t1);
  return vec2(max(max(tmin.x, tmin.y), tmin.z), min(min(tmax.x, tmax.y), tmax.z));
}

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

// Nearest obstacle hit along the ray: analytic for spheres and boxes, sphere tracing for metaballs
// and any other analytic shape.
// Meshes are not traced: liquid/render/mesh_draw.h rasterizes them into the frame's colour and
// depth first, and this pass is depth-tested against them.
float trace_obstacles(vec3 origin, vec3 dir, out int hit_index) {
  float best = k_no_hit;
  hit_index = -1;
  [[unroll]] for (int i = 0; i < obstacle_count(); ++i) {
    Obstacle o = u.obstacles[i];
    int kind = obstacle_kind(i);
    vec3 c = o.center;
    float t = k_no_hit;
    if (kind == LIQUID_OBSTACLE_SPHERE) {
      vec3 oc = origin - c;
      float b = dot(oc, dir), q = dot(oc, oc) - o.sphere_radius * o.sphere_radius, disc = b * b - q;
      if (disc >= 0.0) {
        float s = -b - sqrt(disc);
        if (s > 0.0) t = s;
      }
    } else if (kind == LIQUID_OBSTACLE_BOX) {  // in the box's own frame
      vec4 q = obstacle_frame(i).orientation;
      vec3 local_origin = quat_rotate_inverse(q, origin - c), local_dir = quat_rotate_inverse(q, dir);
      vec2 span = intersect_box(local_origin, 1.0 / local_dir, -o.box_half_extent, o.box_half_extent);
      if (span.x <= span.y && span.x > 0.0) t = span.x;
    } else if (kind != LIQUID_OBSTACLE_MESH) {  // metaballs, and a shape with no ray test of its own
      // Sphere tracing its distance within a sphere about its centre that holds it: the balls'
      // reach, or a bound for a shape whose sphere_radius and box_half_extent are its sizes.
      float reach = o.sphere_radius + length(o.box_half_extent);
      if (kind == LIQUID_OBSTACLE_METABALLS) {
        reach = 0.0;
        for (int b = 0; b < o.ball_count; ++b) {
          vec4 ball = u.balls[o.first_ball + b];
          reach = max(reach, length(ball.xyz) + ball.w);
        }
      }
      vec3 oc = origin - c;
      float bq = dot(oc, dir), disc = bq * bq - (dot(oc, oc) - reach * reach);
      if (disc >= 0.0) {
        float s = max(-bq - sqrt(disc), 0.0), s_end = -bq + sqrt(disc);
        for (int k = 0; k < 48 && s < s_end; ++k) {
          float d = obstacle_distance(i, origin + dir * s);
          if (d < 1e-3) {
            t = s;
            break;
          }
          s += max(d * 0.8, 1e-3);
        }
      }
    }
    if (t < best) {
      best = t;
      hit_index = i;
    }
  }
  return best;
}

vec3 shade_obstacle(int index, vec3 p, vec3 view_dir) {
  // The normal with the obstacle's index the unrolled loop's, as in trace_obstacles(): its kind is
  // then a constant and only its shape's code is compiled. With the run-time index every shape's
  // code, the metaballs' loop included, was inlined into each of the six distances of the central
  // differences, which LLVM 15 took many minutes to compile for two bodies. Written as a loop, not
  // with literal indices (FOR_EACH_OBSTACLE), with which lavapipe's memory grew by 3 MiB a frame
  // (tests/gpu/test_liquid_resources.cpp), as it did when the bisection's count was a uniform: a
  // loop bounded by a uniform it can read at a constant index (the metaballs' count) seems to be
  // compiled again whenever the uniform buffer is rebound.
  vec3 n = vec3(0.0, 1.0, 0.0);
  [[unroll]] for (int i = 0; i < obstacle_count(); ++i)
    if (i == index) n = obstacle_normal(i, p);
  vec3 l = r.sun_direction;
  float diffuse = max(dot(n, l), 0.0);
  float spec = pow(max(dot(n, normalize(l - view_dir)), 0.0), 48.0);
  vec3 base = vec3(0.62, 0.6, 0.58);
  return base * (0.25 + 0.75 * diffuse) + vec3(0.35) * spec + 0.08 * sky(reflect(view_dir, n));
}

// What a ray sees when it does not hit the liquid: an obstacle, the floor or the sky.
vec3 background(vec3 origin, vec3 dir, out float depth_t) {
  int obstacle;
  float t_obstacle = trace_obstacles(origin, dir, obstacle);
  float t_floor = dir.y < -1e-5 ? -origin.y / dir.y : k_no_hit;
  if (t_obstacle < t_floor && t_obstacle < k_no_hit) {
    depth_t = t_obstacle;
    return shade_obstacle(obstacle, origin + dir * t_obstacle, dir);
  }
  if (t_floor < k_no_hit) {
    depth_t = t_floor;
    return floor_color(origin + dir * t_floor);
  }
  depth_t = k_no_hit;
  return sky(dir);
}

// First crossing of the iso level inside [t_enter, t_exit], or k_no_hit.
//
// One loop with one density sample site. Lavapipe runs every line for all 8 lanes and a loop body
// while any lane is active (docs/lavapipe-performance.md), so each sample site inside the loop costs
// every trip of every lane: a trip either crosses an empty brick whole (its largest density, with a
// one-cell border, is below the iso level, so no trilinear value inside it can exceed it) or takes
// one fine step inside an occupied brick. The bisection runs once, after the loop.
float march_liquid(vec3 origin, vec3 dir, float t_enter, float t_exit) {
  float h = cell_size();
  float iso = r.iso_level;
  float fine = r.fine_step_cells * h;
  float brick_size = r.brick_cells * h;
  // Per axis: the t at which the ray leaves a brick is (its lower corner + exit_side - origin) / dir.
  vec3 exit_side = step(0.0, dir) * brick_size;
  vec3 inv_dir = 1.0 / mix(vec3(1e-20), dir, notEqual(dir, vec3(0.0)));
  float nudge = 1e-3 * h;  // past a brick's face, so the next trip looks up the next brick

  float outside_t = t_enter;  // the last point known to be below the iso level
  float t = t_enter;
  bool hit = false;
  for (int i = 0; i < k_max_march_trips && t <= t_exit; ++i) {
    vec3 p = origin + dir * t;
    ivec3 brick = clamp(ivec3(floor(p / brick_size)), ivec3(0), r.bricks - 1);
    vec3 leave = (vec3(brick) * brick_size + exit_side - origin) * inv_dir;
    float brick_end = min(min(leave.x, leave.y), leave.z);
    bool occupied = brick_max_density(brick) > iso;
    float d = density_at(p);
    if (occupied && d > iso) {
      hit = true;
      break;
    }
    outside_t = occupied ? t : brick_end;
    t = occupied ? t + fine : brick_end + nudge;
  }
  // Bisection between the last point outside and the first inside (both t_enter when the ray
  // enters the box inside the liquid). `hit` in the loop's condition, not a return before it: a
  // group of pixels none of which hit makes one trip instead of five (lavapipe runs a loop's body
  // while any lane is active, and at least once; docs/lavapipe-performance.md).
  float a = outside_t, b = t;
  [[dont_unroll]] for (int k = 0; k < k_bisection_steps && hit; ++k) {
    float m = 0.5 * (a + b);
    if (density_at(origin + dir * m) > iso) b = m;
    else a = m;
  }
  return hit ? b : k_no_hit;
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

// The tank's frame: the 12 edges of the domain box as thin bars (radius in metres), so the walls
// the liquid rests against are visible. Returns the nearest hit distance along the ray, or k_no_hit.
//
// Most rays pass nowhere near an edge, so a bound comes first: the distance from the ray to an edge
// is at least the distance, in the plane across the edge's axis, from the edge's point there to the
// ray's shadow line (projecting shortens every distance). The loop below runs only while some pixel
// of the group may be within reach: lavapipe runs a loop's body once for a group whose pixels all
// fail its condition, instead of 12 times. Each such loop here is [[dont_unroll]]: Mesa unrolls a
// loop of a few constant trips, and its exit then becomes an `if` on each copy of the body, which
// lavapipe runs whatever the condition (docs/lavapipe-performance.md, "Every line runs").
bool near_tank_frame(vec3 origin, vec3 dir, float radius) {
  vec3 d = u.domain;
  vec4 corner_u = vec4(0.0, 1.0, 0.0, 1.0), corner_v = vec4(0.0, 0.0, 1.0, 1.0);  // the 4 edges of an axis
  bool near = false;
  [[unroll]] for (int axis = 0; axis < 3; ++axis) {
    int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
    vec4 to_u = corner_u * d[u_axis] - origin[u_axis], to_v = corner_v * d[v_axis] - origin[v_axis];
    vec2 across = vec2(dir[u_axis], dir[v_axis]);
    float across2 = dot(across, across);
    // The squared distance from each edge's point to the shadow line (to the shadow point when the
    // ray runs along the axis).
    vec4 cross_d = across.x * to_v - across.y * to_u;
    vec4 distance2 = across2 > 1e-12 ? cross_d * cross_d / across2 : to_u * to_u + to_v * to_v;
    // A hair over the radius, so that float rounding never drops a pixel the exact test keeps.
    near = near || any(lessThan(distance2, vec4(radius * radius * 1.0001)));
  }
  return near;
}

float trace_tank_frame(vec3 origin, vec3 dir, float radius) {
  vec3 d = u.domain;
  float best = k_no_hit;
  bool near = near_tank_frame(origin, dir, radius);
  [[dont_unroll]] for (int axis = 0; axis < 3 && near; ++axis) {
    for (int corner = 0; corner < 4; ++corner) {
      // Edge along `axis` at the corner of the other two axes picked by the two bits of `corner`.
      vec3 a = vec3(0.0);
      int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
      a[u_axis] = (corner & 1) != 0 ? d[u_axis] : 0.0;
      a[v_axis] = (corner & 2) != 0 ? d[v_axis] : 0.0;
      vec3 e = vec3(0.0);
      e[axis] = d[axis];
      // Closest approach of the ray o + t dir and the segment a + s e, s in [0, 1].
      vec3 w = origin - a;
      float b = dot(dir, e), c = dot(e, e), dd = dot(dir, w), ee = dot(e, w);
      float denom = c - b * b;
      if (abs(denom) < 1e-9) continue;
      float t = (b * ee - c * dd) / denom;
      float s = clamp((ee + t * b) / c, 0.0, 1.0);
      t = dot(a + s * e - origin, dir);
      if (t <= 0.0) continue;
      if (length(origin + t * dir - (a + s * e)) < radius && t < best) best = t;
    }
  }
  return best;
}

float clip_depth(vec3 p) {
  vec4 clip = r.view_projection * vec4(p, 1.0);
  return clamp(clip.z / clip.w, 0.0, 1.0);
}

void main() {
  // The ray through this pixel from the near plane, for any projection: perspective or
  // orthographic, forward or reversed Z, a finite or an infinite far plane (the second point is
  // halfway in clip depth, finite for all of them).
  vec2 ndc = v_uv * 2.0 - 1.0;
  vec4 near_point = r.inverse_view_projection * vec4(ndc, r.near_depth, 1.0);
  vec4 mid_point = r.inverse_view_projection * vec4(ndc, 0.5, 1.0);
  vec3 origin = near_point.xyz / near_point.w;
  vec3 dir = normalize(mid_point.xyz / mid_point.w - origin);

  vec2 span = intersect_box(origin, 1.0 / dir, vec3(0.0), u.domain);
  float t_liquid = k_no_hit;
  if (!BACKGROUND_ONLY && span.x <= span.y && span.y > 0.0) {
    // Do not march past an obstacle in front of the liquid.
    int ignored;
    float t_obstacle = trace_obstacles(origin, dir, ignored);
    t_liquid = march_liquid(origin, dir, max(span.x, 0.0), min(span.y, t_obstacle));
  }

  vec3 color;
  float depth_t;
  if (t_liquid < k_no_hit) {
    vec3 p = origin + dir * t_liquid;
    bool through_wall = span.x > 0.0 && t_liquid <= span.x + 1e-3 * cell_size();
    vec3 n = through_wall ? box_face_normal(p) : density_normal(p, t_liquid < k_no_hit && !through_wall);
    float cos_theta = clamp(dot(-dir, n), 0.0, 1.0);
    float fresnel = 0.02 + 0.98 * pow(1.0 - cos_theta, 5.0);  // Schlick, water F0 = 0.02
    vec3 reflected = sky(reflect(dir, n));
    // Refraction: thickness along the refracted ray (a few coarse steps), then what lies behind.
    // Each step asks the nearest cell, not a trilinear lookup (eight texels): the loop runs to
    // the slowest ray of each group of pixels, and a coarse count needs no more.
    vec3 refracted_dir = refract(dir, n, 1.0 / 1.33);
    if (dot(refracted_dir, refracted_dir) < 1e-6) refracted_dir = dir;
    float thickness = 0.0, step_length = 2.0 * cell_size();
    // Each pixel starts its count at its own fraction of a step (interleaved gradient noise):
    // the nearest-cell samples of neighbouring pixels would otherwise cross the cell layers
    // together and band a face seen straight on (the tank's glass).
    vec2 pixel = gl_FragCoord.xy - vec2(r.viewport_x, r.viewport_y);
    float jitter = fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
    vec3 q = p + refracted_dir * step_length * (jitter - 1.0);
    // Kept a loop (see near_tank_frame): it ends when every ray of the group has left the box.
    [[dont_unroll]] for (int k = 0; k < 16; ++k) {
      q += refracted_dir * step_length;
      if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, u.domain))) break;
      if (fetch_grid(u_density, ivec3(q / cell_size())).r > r.iso_level) thickness += step_length;
    }
    float spec = pow(max(dot(n, normalize(r.sun_direction - dir)), 0.0), 180.0);
    vec3 scattered = vec3(0.01, 0.05, 0.08) * (1.0 - exp(-2.0 * thickness));
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
    float behind_t;
    vec3 behind = background(p + refracted_dir * 1e-3, refracted_dir, behind_t);
    vec3 transmitted = behind * exp(-k_absorption * (thickness + 0.02)) + scattered;
    color = mix(transmitted, reflected, fresnel) + vec3(1.0, 0.97, 0.9) * spec * 1.5;
    depth_t = t_liquid;
  } else {
    if (COMPOSITE) discard;
    color = background(origin, dir, depth_t);
  }

  // The tank frame, in front of whatever else this pixel shows.
  float frame_radius = 0.004 * max(max(u.domain.x, u.domain.y), u.domain.z);
  float t_frame = trace_tank_frame(origin, dir, frame_radius);
  if (t_frame < depth_t) {
    color = vec3(0.16, 0.17, 0.19) * (0.6 + 0.4 * max(r.sun_direction.y, 0.0));
    depth_t = t_frame;
  }

  gl_FragDepth = depth_t < k_no_hit ? clip_depth(origin + dir * depth_t) : 1.0;
  // Filmic-ish tone curve and display encoding (the target is UNORM, written as sRGB values).
  color = color / (1.0 + 0.15 * color);
  out_color = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
