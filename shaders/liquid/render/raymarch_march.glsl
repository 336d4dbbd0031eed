// The raymarch's march (section 7): the rays through the view, the domain box and obstacles they
// cross, and the first crossing of the iso level along them. Shared by the coarse pass
// (raymarch_coarse.frag) and the full-resolution one (raymarch.frag).
#ifndef LIQUID_RAYMARCH_MARCH_GLSL
#define LIQUID_RAYMARCH_MARCH_GLSL

#include "liquid/render/raymarch_view.glsl"

// Both grids are 3D images, or 2D atlases of their slices on the atlas path (ATLAS=1, liquid/solver/grid_layout.h).
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_DENSITY) uniform GRID_SAMPLER u_density;    // rho / rho0, linear filtering
layout(set = 0, binding = LIQUID_BINDING_RAYMARCH_OCCUPANCY) uniform GRID_SAMPLER u_occupancy;  // per-brick max, nearest

const float k_no_hit = LIQUID_RAYMARCH_NO_CROSSING;
// Refinements of a crossing. A constant, not a uniform: lavapipe (Mesa 22.3) compiles a fresh copy
// of a shader whose loop count is read from a uniform block on every draw and keeps every copy
// (2.7 MB per frame of this shader; docs/memory.md).
const int k_bisection_steps = 5;
// A bound on the march's trips (an empty brick or a fine step each), far above what a ray through
// the largest grid needs; the loop ends on t_exit first.
const int k_max_march_trips = 4096;

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

// The part of a ray the liquid can be seen in: from where it enters the domain box (or its origin,
// inside the box) to where it leaves the box or meets an obstacle in front of the liquid. Empty
// (x > y) when the ray misses the box.
vec2 liquid_span(vec3 origin, vec3 dir, vec2 box_span) {
  int ignored;
  float t_obstacle = trace_obstacles(origin, dir, ignored);
  return vec2(max(box_span.x, 0.0), min(box_span.y, t_obstacle));
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

#endif
