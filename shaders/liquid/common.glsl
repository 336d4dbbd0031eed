// Shared by the solver's passes and the views: the per-step uniform block (shared.h), the scene's
// specialization constants and the grid, obstacle and force helpers. DIM is 2 or 3 (a define).
#ifndef LIQUID_COMMON_GLSL
#define LIQUID_COMMON_GLSL
#extension GL_EXT_control_flow_attributes : require

#include "liquid/shared.h"

// The per-step block's fields are named in shared.h (one definition for C++ and GLSL).
layout(std140, set = 0, binding = LIQUID_BINDING_SOLVER_UNIFORMS) uniform SolverBlock {
  SolverUniforms u;
};

// ---- Scene features, fixed when a pipeline is created (specialization constants) ----
// Every pipeline whose shaders include this file passes liquid::scene_specialization(setup)
// (liquid/solver/specialization.cpp; a CPU test checks these ids against it). Why not uniforms: lavapipe
// runs both sides of every branch for every fragment (masked SIMD lanes) and a loop's body at least
// once, so code a scene does not use still costs there, and an obstacle index that varies in a loop
// turns each of its uniform reads into a per-lane gather. With constant counts and kinds the
// obstacle loops unroll to constant indices and unused shapes and terms drop out (the 3D grid pass
// went from 770 to 127 ms of CPU per step). On GPUs this is the usual specialization of an uber-shader.
layout(constant_id = 0) const int OBSTACLE_COUNT = 0;
layout(constant_id = 1) const int OBSTACLE_KIND_0 = 0;
layout(constant_id = 2) const int OBSTACLE_KIND_1 = 0;
layout(constant_id = 3) const int OBSTACLE_KIND_2 = 0;
layout(constant_id = 4) const int OBSTACLE_KIND_3 = 0;
layout(constant_id = 5) const int OBSTACLE_KIND_4 = 0;
layout(constant_id = 6) const int OBSTACLE_KIND_5 = 0;
layout(constant_id = 7) const int OBSTACLE_KIND_6 = 0;
layout(constant_id = 8) const int OBSTACLE_KIND_7 = 0;
layout(constant_id = 9) const bool SHALLOW_WATER = false;  // printed pressure form and ground height
layout(constant_id = 10) const int INTEGER_GAMMA = 0;      // gamma when it is an integer 1..8, else 0
layout(constant_id = 11) const bool HAS_EMITTERS = false;
layout(constant_id = 12) const int GROUND_HILLS = 0;       // shallow water: hills of the ground b(x, y)
// The walls' kernel table is all zeros (the separable splat, whose walls are the liquid continued
// through them): every cell's wall coverage is 1, without a pass over the table per read.
layout(constant_id = 13) const bool WALLS_CONTINUED = false;

int obstacle_count() { return OBSTACLE_COUNT; }

// The solver's loops over the obstacles, written out: CALL(i) for every index up to the limit, i a
// literal, each call skipped unless i < obstacle_count() (a constant once specialized), so an
// obstacle's kind is a constant and only its shape's code is compiled. As `for` loops they were
// left rolled by lavapipe in the MESH_FIELD variants (a loop that, or whose enclosing loop, reads
// the mesh field): each obstacle's kind was then a run-time value and every shape's code ran for
// every obstacle, the metaballs' loop included, which made those passes 4 to 8 times slower.
#if LIQUID_MAX_OBSTACLES != 8
#error FOR_EACH_OBSTACLE lists LIQUID_MAX_OBSTACLES indices
#endif
#define FOR_EACH_OBSTACLE(CALL) CALL(0) CALL(1) CALL(2) CALL(3) CALL(4) CALL(5) CALL(6) CALL(7)

// The constant holds the shape's code (LIQUID_OBSTACLE_SPHERE ...) plus LIQUID_OBSTACLE_DYNAMIC for
// a rigid body the liquid moves.
int obstacle_code(int index) {
  return index == 0 ? OBSTACLE_KIND_0 : index == 1 ? OBSTACLE_KIND_1 : index == 2 ? OBSTACLE_KIND_2
       : index == 3 ? OBSTACLE_KIND_3 : index == 4 ? OBSTACLE_KIND_4 : index == 5 ? OBSTACLE_KIND_5
       : index == 6 ? OBSTACLE_KIND_6 : OBSTACLE_KIND_7;
}
int obstacle_kind(int index) { return obstacle_code(index) & LIQUID_OBSTACLE_SHAPE_MASK; }
bool obstacle_dynamic(int index) { return (obstacle_code(index) & LIQUID_OBSTACLE_DYNAMIC) != 0; }

bool shallow_water() { return SHALLOW_WATER; }

// (rho / rho0)^gamma: repeated products when gamma is a small integer (the default 5), pow otherwise.
float density_ratio_power(float ratio) {
  if (INTEGER_GAMMA == 0) return pow(ratio, u.gamma);
  float result = ratio;
  [[unroll]] for (int i = 1; i < INTEGER_GAMMA; ++i) result *= ratio;
  return result;
}

// ATLAS (3D only): the grids are 2D atlases of their slices (grid_atlas.glsl), not 3D images.
#ifndef ATLAS
#define ATLAS 0
#endif
#include "liquid/grid_atlas.glsl"

// AFFINE: the affine transfer (the scene's "transfer": "affine"): the particles carry C_p, the
// splat deposits u_p + C_p (x_i - x_p) and the particle pass reads C_p back from the grid.
#ifndef AFFINE
#define AFFINE 0
#endif

#if DIM == 3 && !ATLAS
#define GRID_SAMPLER sampler3D
#else
#define GRID_SAMPLER sampler2D
#endif

// A cell holds liquid when its summed splat weight is above this.
const float k_fluid_epsilon = LIQUID_FLUID_EPSILON;

ivec3 grid_cells() { return u.grid_cells; }
ivec2 atlas_tiles() { return ivec2(u.atlas_columns, u.atlas_rows); }
float cell_size() { return u.cell_size; }

// World position (m) of the centre of cell c.
vec3 cell_center(ivec3 c) {
  vec3 p = (vec3(c) + 0.5) * cell_size();
#if DIM == 2
  p.z = 0.0;
#endif
  return p;
}

// The texel of cell c, clamped into the grid (so never an unused atlas tile).
vec4 fetch_grid(GRID_SAMPLER s, ivec3 c) {
  c = clamp(c, ivec3(0), grid_cells() - 1);
#if DIM == 3 && ATLAS
  return texelFetch(s, atlas_texel(c, grid_cells(), atlas_tiles()), 0);
#elif DIM == 3
  return texelFetch(s, c, 0);
#else
  return texelFetch(s, c.xy, 0);
#endif
}

// Index of the cell that mirrors i about the walls of an axis of n cells (-1 -> 0, n -> n - 1).
int mirror_index(int i, int n) { return i < 0 ? -1 - i : (i >= n ? 2 * n - 1 - i : i); }

// Hydrostatic ghost cells beyond the walls (splat-adjoint pressure): a cell c outside the grid
// stands for its mirror image inside, whose pressure it takes, plus the rise of still water's
// pressure over the distance between the two, g.n d on a wall gravity points into. Mirroring alone
// makes dP/dn = 0 at the wall, where still water needs dP/dn = g.n to hold its weight.
// The rise is a sum over the axes; this is axis a's part for a cell at index i along it.
float wall_ghost_rise_along(int a, int i) {
  int n = grid_cells()[a];
  float h = cell_size();
  if (i < 0) return max(-u.gravity[a], 0.0) * float(-2 * i - 1) * h;
  if (i >= n) return max(u.gravity[a], 0.0) * float(2 * (i - n) + 1) * h;
  return 0.0;
}

// ---- Obstacles (section 6): analytic signed distances, negative inside -------------------------

float sd_box(vec3 p, vec3 half_extent) {
  vec3 q = abs(p) - half_extent;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// Metaballs: field F = sum (1 - d^2/R^2)^2 (inside R); surface at F = threshold. The distance is
// the first-order estimate (threshold - F) / |grad F|, exact enough near the surface.
float sd_metaballs(vec3 p, Obstacle o) {
  float field = 0.0;
  vec3 gradient = vec3(0.0);
  float reach = 0.0;
  for (int i = 0; i < o.ball_count; ++i) {
    vec4 ball = u.balls[o.first_ball + i];
    vec3 d = p - ball.xyz;
    float q = dot(d, d) / (ball.w * ball.w);
    reach = max(reach, length(ball.xyz) + ball.w);
    if (q < 1.0) {
      field += (1.0 - q) * (1.0 - q);
      gradient += -4.0 * (1.0 - q) * d / (ball.w * ball.w);
    }
  }
  float threshold = o.metaball_threshold;
  if (field <= 0.0) return max(length(p) - reach, 1e-3) + 1e-3;  // outside every ball
  return (threshold - field) / max(length(gradient), 1e-4);
}

// Rotates v by the unit quaternion q = (x, y, z, w), and by its inverse.
vec3 quat_rotate(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }
vec3 quat_rotate_inverse(vec4 q, vec3 v) { return quat_rotate(vec4(-q.xyz, q.w), v); }

// An obstacle's pose at the step's instant: centre, orientation (shape frame to world), velocity of
// the centre and angular velocity. A scripted or host-placed obstacle's comes from the uniform
// block; a dynamic one's from the body-state texture the integration pass writes (shared.h), in
// shaders that declare it (LIQUID_BODIES: the solver's grid, particle and body passes). Elsewhere
// (the views) a dynamic obstacle is drawn at the pose the node last read back.
struct ObstacleFrame {
  vec3 center;
  vec4 orientation;
  vec3 velocity;
  vec3 angular_velocity;
};

#ifdef LIQUID_BODIES
layout(set = 0, binding = LIQUID_BINDING_BODIES) uniform sampler2D u_bodies;
vec4 body_texel(int index, int texel) { return texelFetch(u_bodies, ivec2(texel, index), 0); }
#endif

ObstacleFrame obstacle_frame(int index) {
  ObstacleFrame f;
#ifdef LIQUID_BODIES
  if (obstacle_dynamic(index)) {
    f.center = body_texel(index, LIQUID_BODY_POSITION).xyz;
    f.orientation = body_texel(index, LIQUID_BODY_ORIENTATION);
    f.velocity = body_texel(index, LIQUID_BODY_VELOCITY).xyz;
    f.angular_velocity = body_texel(index, LIQUID_BODY_ANGULAR_VELOCITY).xyz;
    return f;
  }
#endif
  f.center = u.obstacles[index].center;
  f.orientation = u.obstacles[index].orientation;
  f.velocity = u.obstacles[index].velocity;
  f.angular_velocity = u.obstacles[index].angular_velocity;
  return f;
}

// p relative to obstacle `index`'s centre (in the plane in 2D).
vec3 obstacle_offset(int index, vec3 p) {
  vec3 offset = p - obstacle_frame(index).center;
#if DIM == 2
  offset.z = 0.0;
#endif
  return offset;
}

// The velocity of the obstacle's material at p: v + w x (p - c).
vec3 obstacle_velocity_at(int index, vec3 p) {
  ObstacleFrame f = obstacle_frame(index);
  return f.velocity + cross(f.angular_velocity, p - f.center);
}

// Mesh obstacles (MESH_FIELD=1, the passes of scenes with meshes): their signed distance, built on
// the grid by the rasterizer (liquid/solver/mesh_field.h), one channel per mesh in scene order,
// exact within obstacle_band + LIQUID_MESH_FIELD_MARGIN_CELLS cells of the surface, clamped beyond.
// A pass reads every mesh's distance at a point with one lookup (MeshSample) before its loop over
// the obstacles: a texture lookup inside that loop keeps lavapipe from unrolling it (the kinds are
// then no longer constants, and the 3D grid pass ran ten times slower).
#ifndef MESH_FIELD
#define MESH_FIELD 0
#endif
#if MESH_FIELD
layout(set = 0, binding = LIQUID_BINDING_MESH_FIELD) uniform GRID_SAMPLER u_mesh_field;
#endif

// Every mesh's distance (m) at a point and, where asked, its gradient (unnormalised). Plain
// members, no array: lavapipe keeps an array of a struct in memory, not in registers.
struct MeshSample {
  vec4 distance;
  vec4 gradient_x, gradient_y, gradient_z;
};

// Channel `slot` of v, by selects (an index into a vector can also be lowered to memory).
float channel(vec4 v, int slot) { return slot == 0 ? v.x : slot == 1 ? v.y : slot == 2 ? v.z : v.w; }

// The channel of obstacle `index`: how many meshes come before it (constant once specialized;
// written out rather than as a loop, which nested in the obstacle loops kept lavapipe from
// unrolling them).
int mesh_before(int index, int j, int kind) { return j < index && kind == LIQUID_OBSTACLE_MESH ? 1 : 0; }
int mesh_slot(int index) {
  return mesh_before(index, 0, OBSTACLE_KIND_0) + mesh_before(index, 1, OBSTACLE_KIND_1) +
         mesh_before(index, 2, OBSTACLE_KIND_2) + mesh_before(index, 3, OBSTACLE_KIND_3) +
         mesh_before(index, 4, OBSTACLE_KIND_4) + mesh_before(index, 5, OBSTACLE_KIND_5) +
         mesh_before(index, 6, OBSTACLE_KIND_6);
}

// Dynamic meshes (rigid bodies from triangle meshes, 3D): their distance is not in the mesh field
// (which the host's and scripted meshes' poses place) but in the body-shape texture, one channel
// per dynamic mesh, in the body's own frame about its centre of mass (liquid/solver/body_shapes.h),
// sampled at the pose in the body-state texture, as a box's distance is evaluated in its frame.
bool mesh_body(int index) {
  return obstacle_kind(index) == LIQUID_OBSTACLE_MESH && obstacle_dynamic(index);
}
int mesh_body_before(int index, int j, int code) {
  return j < index && code == (LIQUID_OBSTACLE_MESH | LIQUID_OBSTACLE_DYNAMIC) ? 1 : 0;
}
int mesh_body_slot(int index) {
  return mesh_body_before(index, 0, OBSTACLE_KIND_0) + mesh_body_before(index, 1, OBSTACLE_KIND_1) +
         mesh_body_before(index, 2, OBSTACLE_KIND_2) + mesh_body_before(index, 3, OBSTACLE_KIND_3) +
         mesh_body_before(index, 4, OBSTACLE_KIND_4) + mesh_body_before(index, 5, OBSTACLE_KIND_5) +
         mesh_body_before(index, 6, OBSTACLE_KIND_6);
}
// Declared with the body state (LIQUID_BODIES) in the passes that evaluate obstacles' distances;
// the integration pass (LIQUID_BODY_STATE_ONLY) reads the state alone.
#if defined(LIQUID_BODIES) && !defined(LIQUID_BODY_STATE_ONLY)
#define LIQUID_BODY_SHAPES
#endif
#ifdef LIQUID_BODY_SHAPES
layout(set = 0, binding = LIQUID_BINDING_BODY_SHAPES) uniform sampler3D u_body_shapes;
// `offset` from the body's centre (world axes): trilinear in its cube of side 2 s (s in
// sphere_radius), past the cube its value at the cube's face plus the distance to the cube.
float mesh_body_distance(int index, vec3 offset) {
  vec3 local = quat_rotate_inverse(obstacle_frame(index).orientation, offset);
  float half_size = u.obstacles[index].sphere_radius;
  vec3 uvw = clamp(local / (2.0 * half_size) + 0.5, 0.0, 1.0);
  float d = channel(textureLod(u_body_shapes, uvw, 0.0), mesh_body_slot(index));
  return d + length(max(abs(local) - half_size, 0.0));
}
#endif

// A grid image with linear filtering at point p (m): trilinear between cell centres (bilinear in
// 2D), clamped to the grid's edge.
vec4 sample_grid_linear(GRID_SAMPLER s, vec3 p) {
  vec3 uvw = p / (vec3(grid_cells()) * cell_size());
#if DIM == 2
  return textureLod(s, uvw.xy, 0.0);
#elif ATLAS
  return atlas_sample_linear(s, uvw, grid_cells(), atlas_tiles());
#else
  return textureLod(s, uvw, 0.0);
#endif
}

#if MESH_FIELD
vec4 mesh_field_at(vec3 p) { return sample_grid_linear(u_mesh_field, p); }
#endif

// At any point (the particle pass): filtered, the gradient by central differences a quarter cell apart.
MeshSample mesh_sample(vec3 p, bool with_gradient) {
  MeshSample m;
  m.distance = vec4(LIQUID_MESH_FAR);
  m.gradient_x = m.gradient_y = m.gradient_z = vec4(0.0);
#if MESH_FIELD
  m.distance = mesh_field_at(p);
  if (with_gradient) {
    float e = 0.25 * cell_size();
    m.gradient_x = mesh_field_at(p + vec3(e, 0.0, 0.0)) - mesh_field_at(p - vec3(e, 0.0, 0.0));
    m.gradient_y = mesh_field_at(p + vec3(0.0, e, 0.0)) - mesh_field_at(p - vec3(0.0, e, 0.0));
#if DIM == 3
    m.gradient_z = mesh_field_at(p + vec3(0.0, 0.0, e)) - mesh_field_at(p - vec3(0.0, 0.0, e));
#endif
  }
#endif
  return m;
}

// Every mesh's distance at cell c's centre (the grid passes): its texel (far without MESH_FIELD).
vec4 mesh_distances_at_cell(ivec3 c) {
#if MESH_FIELD
  return fetch_grid(u_mesh_field, c);
#else
  return vec4(LIQUID_MESH_FAR);
#endif
}

// The meshes' distances at a point, without a gradient.
MeshSample mesh_sample_of(vec4 distance) {
  MeshSample m;
  m.distance = distance;
  m.gradient_x = m.gradient_y = m.gradient_z = vec4(0.0);
  return m;
}

// At cell c's centre (the grid passes): the texel itself, the gradient a cell either side.
MeshSample mesh_sample_at_cell(ivec3 c, bool with_gradient) {
  MeshSample m = mesh_sample_of(mesh_distances_at_cell(c));
  if (with_gradient) {
    m.gradient_x = mesh_distances_at_cell(c + ivec3(1, 0, 0)) - mesh_distances_at_cell(c - ivec3(1, 0, 0));
    m.gradient_y = mesh_distances_at_cell(c + ivec3(0, 1, 0)) - mesh_distances_at_cell(c - ivec3(0, 1, 0));
#if DIM == 3
    m.gradient_z = mesh_distances_at_cell(c + ivec3(0, 0, 1)) - mesh_distances_at_cell(c - ivec3(0, 0, 1));
#endif
  }
  return m;
}

// Signed distance of obstacle `index` at p; a mesh's from `meshes` (sampled at p), a dynamic
// mesh's from the body-shape texture (far in shaders without the body state: the views draw it
// as a mesh). Only a box and a dynamic mesh turn their distance with their orientation (a sphere's
// does not change, metaballs take no rotation, a static mesh is voxelized turned), so the others
// skip the quaternion.
float obstacle_distance(int index, vec3 p, MeshSample meshes) {
  Obstacle o = u.obstacles[index];
  vec3 offset = obstacle_offset(index, p);
  int kind = obstacle_kind(index);
  if (mesh_body(index)) {
#ifdef LIQUID_BODY_SHAPES
    return mesh_body_distance(index, offset);
#else
    return LIQUID_MESH_FAR;
#endif
  }
  if (kind == LIQUID_OBSTACLE_MESH) return channel(meshes.distance, mesh_slot(index));
  if (kind == LIQUID_OBSTACLE_SPHERE) return length(offset) - o.sphere_radius;
  if (kind == LIQUID_OBSTACLE_BOX) {
    vec3 local = quat_rotate_inverse(obstacle_frame(index).orientation, offset);  // the box's own frame
#if DIM == 2
    return sd_box(local, vec3(o.box_half_extent.xy, 1.0));  // the rectangle's distance in the plane
#else
    return sd_box(local, o.box_half_extent);
#endif
  }
  return sd_metaballs(offset, o);
}

// The analytic shapes' alone (a mesh is far: the views draw meshes another way).
float obstacle_distance(int index, vec3 p) {
  MeshSample none;
  none.distance = vec4(LIQUID_MESH_FAR);
  return obstacle_distance(index, p, none);
}

// Outward normal: exact for a sphere, a static mesh's from its gradient in `meshes`, by central
// differences for the other kinds (a dynamic mesh's of its body-shape distance).
vec3 obstacle_normal(int index, vec3 p, MeshSample meshes) {
  vec3 n;
  if (obstacle_kind(index) == LIQUID_OBSTACLE_SPHERE) {
    n = obstacle_offset(index, p);
  } else if (obstacle_kind(index) == LIQUID_OBSTACLE_MESH && !obstacle_dynamic(index)) {
    int slot = mesh_slot(index);
    n = vec3(channel(meshes.gradient_x, slot), channel(meshes.gradient_y, slot), channel(meshes.gradient_z, slot));
  } else {
    float e = 0.25 * cell_size();
    n = vec3(obstacle_distance(index, p + vec3(e, 0, 0)) - obstacle_distance(index, p - vec3(e, 0, 0)),
             obstacle_distance(index, p + vec3(0, e, 0)) - obstacle_distance(index, p - vec3(0, e, 0)), 0.0);
#if DIM == 3
    n.z = obstacle_distance(index, p + vec3(0, 0, e)) - obstacle_distance(index, p - vec3(0, 0, e));
#endif
  }
  float len = length(n);
  return len > 1e-12 ? n / len : vec3(0.0, 1.0, 0.0);
}

vec3 obstacle_normal(int index, vec3 p) {
  MeshSample none;
  none.distance = vec4(LIQUID_MESH_FAR);
  none.gradient_x = none.gradient_y = none.gradient_z = vec4(0.0);
  return obstacle_normal(index, p, none);
}

// Artificial obstacle density (section 6): rho0 at the surface, rising linearly inside and falling
// to zero one band outside. Added to the fluid density before the pressure, so the pressure
// gradient pushes liquid away from the obstacle. A dynamic obstacle adds none: the pressure is
// clamped at 0 below rho0 (pressure_from_density), so any density an obstacle adds where liquid is
// acts as a wall a band further out, and a body riding on that cushion floats a band too high.
// The liquid next to a body reads its density with the body's kernel coverage instead, as at the
// walls (body_coverage in grid_update.glsl; docs/physics.md, "Bodies that float").
float obstacle_density(vec3 p, MeshSample meshes) {
  float band = u.obstacle_band;
  float total = 0.0;
#define LIQUID_DENSITY_TERM(i) \
  if (i < obstacle_count() && !obstacle_dynamic(i)) \
    total += clamp(1.0 - obstacle_distance(i, p, meshes) / band, 0.0, 2.0);
  FOR_EACH_OBSTACLE(LIQUID_DENSITY_TERM)
#undef LIQUID_DENSITY_TERM
  return total * u.rest_density;
}

// At cell c's centre (the grid passes), where the meshes' distances are `meshes` (read there).
float obstacle_density_at_cell(ivec3 c, vec4 meshes) { return obstacle_density(cell_center(c), mesh_sample_of(meshes)); }
float obstacle_density_at_cell(ivec3 c) { return obstacle_density_at_cell(c, mesh_distances_at_cell(c)); }

// Shallow water (section 6, figure 4): ground height b(x, y) in metres; read as extra density
// rho0 * b / rest_depth so that P = g (h + b).
float ground_height(vec2 p) {
  float b = 0.0;
  [[unroll]] for (int i = 0; i < GROUND_HILLS; ++i) {
    vec4 hill = u.ground[i];
    vec2 d = p - hill.xy;
    b += hill.z * exp(-dot(d, d) / (2.0 * hill.w * hill.w));
  }
  return b;
}

// External forces f_ext (eq. 2): brushes with a smooth (1 - d^2/R^2)^2 falloff.
vec3 brush_acceleration(Brush b, vec3 p) {
  vec3 d = p - b.position;
#if DIM == 2
  d.z = 0.0;
#endif
  float q = dot(d, d) / (b.radius * b.radius);
  return q < 1.0 ? b.acceleration * (1.0 - q) * (1.0 - q) : vec3(0.0);
}
// At p, summed over the brushes.
vec3 external_acceleration(vec3 p) {
  vec3 a = vec3(0.0);
  for (int i = 0; i < u.brush_count; ++i) a += brush_acceleration(u.brushes[i], p);
  return a;
}

// Keeps a position inside the box [lo, hi] (z pinned to 0 in 2D).
vec3 clamp_to_bounds(vec3 p, vec3 lo, vec3 hi) {
  p = clamp(p, lo, hi);
#if DIM == 2
  p.z = 0.0;
#endif
  return p;
}

// Keeps a position inside the domain, `margin` metres from every wall.
vec3 clamp_to_domain(vec3 p) { return clamp_to_bounds(p, vec3(u.wall_margin), u.domain - u.wall_margin); }

// The box a particle moving from `start` is kept in: `wall_margin` inside the walls, or where it
// started if that is closer (the initial lattice's first layer sits half a spacing from a wall). It
// may not move further toward the wall, but is not snapped out to the margin either: snapping a
// whole layer at once piled it onto the next and kicked liquid off the walls at the free surface.
void domain_bounds_from(vec3 start, out vec3 lo, out vec3 hi) {
  lo = min(vec3(u.wall_margin), start);
  hi = max(u.domain - u.wall_margin, start);
}

#endif
