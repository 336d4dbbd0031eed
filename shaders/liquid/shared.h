// The one source of every number and layout the liquid's C++ and GLSL share: limits, obstacle-kind
// codes, descriptor binding numbers and the solver's per-step uniform block. Included by
// liquid/solver/gpu_types.h (C++, std140 checked by static_asserts there and by a SPIR-V reflection
// test), directly by the scene checks and CPU physics for the limits, and by
// shaders/liquid/common.glsl.
#ifndef LIQUID_SHARED_H
#define LIQUID_SHARED_H

// ---- Limits -------------------------------------------------------------------------------------
#define LIQUID_MAX_OBSTACLES 8
#define LIQUID_MAX_BALLS 32           // metaballs over all obstacles
#define LIQUID_MAX_GROUND_HILLS 16    // shallow water
#define LIQUID_MAX_BRUSHES 4          // external force brushes per step
#define LIQUID_MAX_EMITTERS 4
// Splat radius r in cells: the scene check's upper bound, and the size of the wall-kernel table
// (one entry per whole cell a wall can be from a cell centre while the kernel still reaches it).
#define LIQUID_MAX_KERNEL_RADIUS_CELLS 8
#define LIQUID_WALL_TABLE_SIZE LIQUID_MAX_KERNEL_RADIUS_CELLS
// A cell whose summed kernel weight is below this holds no liquid (its velocity is not sampled).
#define LIQUID_FLUID_EPSILON 1e-6

// ---- Obstacle kinds (the OBSTACLE_KIND_i specialization constants) ------------------------------
// ObstacleShape's values (include/liquid/scene.h); a new shape's distance goes in common.glsl's
// obstacle_distance() and liquid/physics/obstacles.cpp, and the views trace it by that distance.
#define LIQUID_OBSTACLE_SPHERE 0
#define LIQUID_OBSTACLE_BOX 1
#define LIQUID_OBSTACLE_METABALLS 2
#define LIQUID_OBSTACLE_MESH 3        // a triangle mesh voxelized into the mesh field each step it moves
// Added to a kind for a dynamic obstacle (a rigid body the liquid moves): its pose is read from the
// body-state texture, not from the uniform block (obstacle_frame() in common.glsl).
#define LIQUID_OBSTACLE_DYNAMIC 8
#define LIQUID_OBSTACLE_SHAPE_MASK 7

// ---- Rigid bodies: the body-state texture (RGBA32F, one row per obstacle) ------------------------
// Texel x of row i holds, for a dynamic obstacle i (rows of other obstacles are unused):
#define LIQUID_BODY_POSITION 0          // xyz centre (m)
#define LIQUID_BODY_ORIENTATION 1       // unit quaternion (x, y, z, w), body to world
#define LIQUID_BODY_VELOCITY 2          // xyz m/s
#define LIQUID_BODY_ANGULAR_VELOCITY 3  // xyz rad/s (world frame)
#define LIQUID_BODY_FORCE 4             // xyz N: the liquid's force over the last step (reported)
#define LIQUID_BODY_TORQUE 5            // xyz N m about the centre (reported)
#define LIQUID_BODY_ACCELERATION 6      // xyz m/s^2 of the last step (the added-mass term)
#define LIQUID_BODY_ANGULAR_ACCELERATION 7
#define LIQUID_BODY_TEXELS 8
// The body force pass's two targets (one texel per obstacle): force (N) and torque (N m).
#define LIQUID_BODY_TARGET_FORCE 0
#define LIQUID_BODY_TARGET_TORQUE 1

// Mesh obstacles: each has one channel of the mesh field (RGBA), so at most four per scene.
#define LIQUID_MAX_MESH_OBSTACLES 4
// The mesh field holds the signed distance (m) within this many cells beyond the obstacle band
// (obstacle_band + this * h); further out it is clamped there. The grid pass's density needs the
// band and its normal a quarter cell more (obstacle_normal's central differences).
#define LIQUID_MESH_FIELD_MARGIN_CELLS 0.5
// The seed pass writes each triangle's exact closest point into the cells within this many cells of
// it, and the jump flood carries them on to the whole band: the field is exact there, where the
// grid pass reads the normal, and a little over beyond. With 1 cell a mesh sphere stirred a 3D pool
// 5 % off the analytic sphere's energy, and 7 % with 0.87 (tests/gpu/test_mesh_obstacles.cpp). The
// seed pass's cost grows with its slices per triangle and the cells around it in each.
#define LIQUID_MESH_SEED_CELLS 1.5
// The closest point of a cell no seed reached, and what a mesh's field draw leaves in the other
// meshes' channels (MIN blending keeps the smaller); above any band.
#define LIQUID_MESH_FAR 1.0e4
// How far from a static obstacle's surface the particle pass keeps the particles, in cells
// (particle.frag); under the pressure projection also how far the fill carves the blocks around it.
#define LIQUID_OBSTACLE_SKIN_CELLS 0.5

// Secondary particles (liquid/solver/whitewater.h): the most slots a liquid particle owns, and the
// kinds a slot's position.w holds (0: free).
#define LIQUID_MAX_WHITEWATER_SLOTS 8
#define LIQUID_WHITEWATER_FREE 0
#define LIQUID_WHITEWATER_SPRAY 1
#define LIQUID_WHITEWATER_FOAM 2
#define LIQUID_WHITEWATER_BUBBLE 3
// Steps between two spawning passes (the others only move what lives).
#define LIQUID_WHITEWATER_SPAWN_INTERVAL 8

// ---- Descriptor bindings (set 0, push descriptors) ----------------------------------------------
// Every pipeline that includes common.glsl has the solver's uniform block at binding 0.
#define LIQUID_BINDING_SOLVER_UNIFORMS 0
// Splat: the particle textures, read by the vertex stage.
#define LIQUID_BINDING_SPLAT_POSITIONS 1
#define LIQUID_BINDING_SPLAT_VELOCITIES 2
// The affine transfer's C_p textures (variant.affine_textures() of them, from this binding on).
#define LIQUID_BINDING_SPLAT_AFFINE 3
// Grid pass: the splatted grid; with the splat-adjoint pressure, the smoothed pressure Phi.
#define LIQUID_BINDING_GRID_SPLAT 1
#define LIQUID_BINDING_GRID_POTENTIAL 2
// Grid pass under the pressure projection: the row pass's system, whose 4th channel is the cells'
// liquid fraction.
#define LIQUID_BINDING_GRID_PROJECTION_SYSTEM 3
// Splat-adjoint pressure passes: the splat (pressure.frag), the cells' pressure (potential.frag).
#define LIQUID_BINDING_PRESSURE_SPLAT 1
#define LIQUID_BINDING_POTENTIAL_PRESSURE 1
// The pressure projection's Jacobi passes: the last iterate and the system (the divergence pass's).
#define LIQUID_BINDING_PROJECTION_PRESSURE 2
#define LIQUID_BINDING_PROJECTION_SYSTEM 3
// The separable splat's and potential's passes along one axis: the grid they spread.
#define LIQUID_BINDING_BLUR_SOURCE 1
#define LIQUID_BINDING_BLUR_SOURCE_UPPER 2  // the 3D deposit's second grid (the z pass)
// Particle update: the particles, the splatted grid (u for FLIP) and the grid pass's u'.
#define LIQUID_BINDING_PARTICLE_POSITIONS 1
#define LIQUID_BINDING_PARTICLE_VELOCITIES 2
#define LIQUID_BINDING_PARTICLE_SPLAT 3
#define LIQUID_BINDING_PARTICLE_GRID_VELOCITY 4
// The separable splat's deposit (bilinear weights at the cell centres, before the spreads): the
// particle pass's fine density for the position correction. 3D: its upper slices' shares too.
#define LIQUID_BINDING_PARTICLE_DEPOSIT 6
#define LIQUID_BINDING_PARTICLE_DEPOSIT_UPPER 10
// Under the pressure projection: the grid pass's density correction, -grad psi (projection.glsl).
#define LIQUID_BINDING_PARTICLE_CORRECTION 11
// The particle pass's own specialization constant, after the scene's (liquid/solver/specialization.h):
// whether it runs the position correction.
#define LIQUID_PARTICLE_POSITION_CORRECTION_ID 14
// The body-state texture, read where dynamic obstacles are evaluated (grid, particle, body passes).
#define LIQUID_BINDING_BODIES 5
// The body force and exchange passes read the splat at LIQUID_BINDING_GRID_SPLAT, as the grid pass
// does (the pressure they integrate, the velocity the no-inflow condition meets); the exchange
// pass the particles' positions at its own. The integration pass: their force and torque.
#define LIQUID_BINDING_BODY_PARTICLES 2
// With the splat-adjoint pressure, the body force pass reads pressure.frag's cell pressure P.
#define LIQUID_BINDING_BODY_CELL_PRESSURE 3
#define LIQUID_BINDING_BODY_FORCE 1
#define LIQUID_BINDING_BODY_TORQUE 2
// The mesh obstacles' signed distance field (the MESH_FIELD variants of the grid, pressure and
// particle passes and of the 2D view), and the passes that build it (liquid/solver/mesh_field.h).
#define LIQUID_BINDING_MESH_FIELD 7  // past the bodies' 5
// The dynamic meshes' distance in their own frames (liquid/solver/body_shapes.h), read with the
// body state wherever dynamic obstacles are evaluated (LIQUID_BODIES).
#define LIQUID_BINDING_BODY_SHAPES 8
#define LIQUID_BINDING_MESH_TRIANGLES 1     // mesh_raster.vert, mesh_draw.vert: the triangles' corners
#define LIQUID_BINDING_MESH_INSIDE 1        // mesh_spread.frag (the field): the signed crossing counts
#define LIQUID_BINDING_MESH_NEAREST 2       // mesh_spread.frag: the closest surface points so far
#define LIQUID_BINDING_MESH_REFERENCE 1     // mesh_resample.frag: the mesh's reference field
// Views.
// The active region (liquid/solver/active_region.h): the 3D grid passes' vertex shader reads the
// rectangle of each slice; the reduction passes read the marks (a grid) and then the rows' spans.
#define LIQUID_BINDING_ACTIVE_REGION 9
#define LIQUID_BINDING_ACTIVE_MARKS 1
#define LIQUID_BINDING_ACTIVE_ROWS 1
// The active region is a rectangle per band of this many rows of each slice, so the air between a
// pool and liquid above it is skipped too.
#define LIQUID_ACTIVE_REGION_BAND_ROWS 8
#define LIQUID_BINDING_VIEW_UNIFORMS 1      // raymarch, height field: the view's own block
#define LIQUID_BINDING_VIEW2D_DENSITY 1
#define LIQUID_BINDING_VIEW2D_DEPTH 2        // view2d.frag: view2d_depth.frag's depth below the surface
#define LIQUID_BINDING_HEIGHT_FIELD_DENSITY 2
#define LIQUID_BINDING_RAYMARCH_DENSITY 2
#define LIQUID_BINDING_RAYMARCH_OCCUPANCY 3
#define LIQUID_BINDING_RAYMARCH_COARSE 4    // the coarse march's crossings (raymarch_coarse.frag)
#define LIQUID_BINDING_RAYMARCH_TILES 5     // the screen tiles' kinds (raymarch_tiles.frag)
#define LIQUID_BINDING_OCCUPANCY_DENSITY 0
#define LIQUID_BINDING_PARTICLES2D_POSITIONS 0
// The whitewater pass (whitewater.frag) reads the liquid's particles and grids at the particle
// pass's bindings, the bodies and meshes at theirs, and its own two textures here.
#define LIQUID_BINDING_WHITEWATER_POSITIONS 10
#define LIQUID_BINDING_WHITEWATER_VELOCITIES 11
#define LIQUID_BINDING_WHITEWATER_DENSITY 12
#define LIQUID_BINDING_WHITEWATER_DRAW_POSITIONS 0  // whitewater_draw.vert

// ---- The solver's per-step uniform block (std140) ------------------------------------------------
// Written once for both languages: in C++ the types are glm's and every struct is 16-byte aligned,
// which is what std140 does with structs; LIQUID_ALIGN16 marks the members std140 moves to a
// 16-byte boundary after a lone scalar. Fields are grouped in fours so no vec3 straddles a boundary.
// LIQUID_PUSH marks a push-constant block (std430: no 16-byte rounding); shaders/liquid/render/
// view_blocks.h uses these macros too.
#ifdef __cplusplus
#include <glm/glm.hpp>
namespace liquid::gpu {
using glm::ivec3;
using glm::ivec4;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
// The limits and codes above under C++ names, for the scene checks and the CPU physics, which
// include this file directly (it sits below every folder of liquid/).
constexpr int k_max_obstacles = LIQUID_MAX_OBSTACLES;
constexpr int k_max_balls = LIQUID_MAX_BALLS;
constexpr int k_max_ground_hills = LIQUID_MAX_GROUND_HILLS;
constexpr int k_max_brushes = LIQUID_MAX_BRUSHES;
constexpr int k_max_emitters = LIQUID_MAX_EMITTERS;
constexpr int k_max_kernel_radius_cells = LIQUID_MAX_KERNEL_RADIUS_CELLS;
constexpr int k_wall_table_size = LIQUID_WALL_TABLE_SIZE;
constexpr float k_fluid_epsilon = float(LIQUID_FLUID_EPSILON);

constexpr int k_obstacle_dynamic = LIQUID_OBSTACLE_DYNAMIC;
constexpr int k_body_texels = LIQUID_BODY_TEXELS;
constexpr int k_max_mesh_obstacles = LIQUID_MAX_MESH_OBSTACLES;
constexpr float k_mesh_field_margin_cells = float(LIQUID_MESH_FIELD_MARGIN_CELLS);
constexpr float k_mesh_seed_cells = float(LIQUID_MESH_SEED_CELLS);
constexpr int k_max_whitewater_slots = LIQUID_MAX_WHITEWATER_SLOTS;
}  // namespace liquid::gpu
#define LIQUID_STRUCT(name) struct alignas(16) name
#define LIQUID_ALIGN16 alignas(16)
#define LIQUID_PUSH(name) struct name
#else
#define LIQUID_STRUCT(name) struct name
#define LIQUID_ALIGN16
#define LIQUID_PUSH(name) struct name
#endif

#ifdef __cplusplus
namespace liquid::gpu {
#endif

LIQUID_STRUCT(Obstacle) {
  vec3 center;              // m, at the end of the step
  float sphere_radius;      // m; a dynamic mesh: half the side of its cube in the body-shape texture
  vec3 box_half_extent;     // m; a dynamic mesh: its bounds' half extent about its centre (wall contact)
  float metaball_threshold; // surface where sum (1 - d^2/R^2)^2 reaches it
  vec3 velocity;            // m/s, of the centre
  int first_ball;           // metaballs: first entry in balls[]
  int ball_count;
  LIQUID_ALIGN16 vec4 orientation;  // unit quaternion (x, y, z, w), the shape's frame to world
  vec3 angular_velocity;    // rad/s, world frame: a point p moves at velocity + w x (p - center)
};

// A dynamic obstacle's rigid-body constants, read by the integration pass (body.frag).
LIQUID_STRUCT(Body) {
  vec3 inertia;             // kg m^2, principal moments in the shape's frame (2D: per metre of depth)
  float mass;               // kg (2D: per metre of depth)
  vec3 external_force;      // N, the host's (LiquidNode::set_body_force), through the centre
  float added_mass;         // kg, the integrator's added-mass term (docs/physics.md)
  vec3 external_torque;     // N m
  float added_inertia_ratio;  // the same for rotation, as a fraction of the inertia
};

LIQUID_STRUCT(Brush) {     // f_ext (eq. 2): acceleration falling smoothly to zero at the radius
  vec3 position;           // m
  float radius;            // m
  vec3 acceleration;       // m/s^2 at the centre
};

LIQUID_STRUCT(EmitterRange) {
  vec3 position;           // nozzle centre, m
  float radius;            // nozzle radius, m
  vec3 velocity;           // m/s
  int first;               // first particle index emitted this step
  int end;                 // one past the last
};

// The step's scalars, a line each. The block below declares them from this list, in C++ and in
// GLSL, and tests/cpu/test_shaders.cpp checks every one's offset against glslang's: a new scalar
// is one line here (before the arrays, where std140 and C++ agree on scalars and vec3s followed
// by a scalar) and its value in make_uniforms().
#define LIQUID_SOLVER_SCALARS(X)                                                                     \
  X(vec3, domain)                 /* m */                                                            \
  X(float, cell_size)             /* h, m */                                                         \
  X(ivec3, grid_cells)                                                                               \
  X(int, particle_texture_width)                                                                     \
  X(vec3, gravity)                /* m/s^2 */                                                        \
  X(float, dt)                    /* s */                                                            \
  X(float, stiffness)             /* k, m^2/s^2 */                                                   \
  X(float, gamma)                                                                                    \
  X(float, rest_density)          /* rho0, kg/m^3 */                                                 \
  X(float, density_scale)         /* kg/m^3 per unit of summed kernel weight */                      \
  X(float, kernel_radius)         /* r, cells */                                                     \
  X(float, pic_ratio)             /* r of section 5.1's PIC/FLIP blend */                            \
  X(float, wall_margin)           /* m, particles are kept this far from every wall (or start) */    \
  X(float, obstacle_band)         /* m, the artificial obstacle density falls to zero this far out */ \
  X(int, active_before)           /* particles alive at the start of the step */                     \
  X(int, active_after)            /* after this step's emission */                                   \
  X(int, brush_count)                                                                                \
  X(int, emission_count)          /* emitters adding particles this step */                          \
  X(float, rest_depth)            /* shallow water: depth at rest, m */                              \
  X(int, atlas_columns)           /* the atlas path's columns and rows of slice tiles */             \
  X(int, atlas_rows)              /* (liquid/solver/grid_layout.h); 1 and 1 otherwise */             \
  X(int, active_region_margin_cells)  /* 3D: the grid passes' region past the marks */

#define LIQUID_DECLARE_MEMBER(type, name) type name;

LIQUID_STRUCT(SolverUniforms) {
  LIQUID_SOLVER_SCALARS(LIQUID_DECLARE_MEMBER)
  // Fraction of the kernel's mass beyond a wall k + 0.5 cells from a cell centre: [k / 4][k % 4].
  LIQUID_ALIGN16 vec4 wall_kernel_beyond[LIQUID_WALL_TABLE_SIZE / 4];
  Obstacle obstacles[LIQUID_MAX_OBSTACLES];
  vec4 balls[LIQUID_MAX_BALLS];         // metaballs: xyz centre relative to the obstacle (m), w radius (m)
  vec4 ground[LIQUID_MAX_GROUND_HILLS]; // hills: xy centre (m), z height (m), w width (m)
  Brush brushes[LIQUID_MAX_BRUSHES];
  EmitterRange emitters[LIQUID_MAX_EMITTERS];
  Body bodies[LIQUID_MAX_OBSTACLES];
  // The same share beyond a dynamic body's surface k + 0.5 cells from a cell centre, as the
  // scene's lattice sees it (uniform liquid reads its rest density there): [k / 4][k % 4].
  vec4 body_kernel_beyond[LIQUID_WALL_TABLE_SIZE / 4];
  // 1 when the walls are the liquid continued through them (the separable splat's mirror images):
  // the kernel then also lacks a dynamic body's mirror image beyond a wall (pressure.glsl).
  int body_images_beyond_walls;
  // The particle pass's position correction (particle.frag): beta (0: off), and rho / rho0 per
  // unit of the separable splat's deposited bilinear weight.
  float position_correction;
  float deposit_density_scale;
  int unused_0;
};

// The textures of a mesh's triangles (3 texels per triangle: its corners in the mesh's frame) are
// this many texels wide.
#define LIQUID_MESH_TRIANGLE_TEXTURE_WIDTH 1024

// The whitewater pass's push constants (liquid/solver/whitewater.cpp, whitewater.frag): the scene's
// Whitewater settings and the step's time. Scalars only, so std430 and C++ agree without padding.
LIQUID_PUSH(WhitewaterPush) {
  float time;               // s, at the end of the step
  float dt;                 // s
  int step;                 // the step's number, which seeds the spawns' random numbers
  int slots;                // per liquid particle
  int owner_rows;           // rows of the liquid's particle texture (slot k's rows follow k of them)
  float lifetime;           // s
  float trapped_air_rate;   // 1/s
  float crest_rate;         // 1/s
  float trapped_air_lo;     // m/s
  float trapped_air_hi;
  float crest_lo;           // 1/m
  float crest_hi;
  float speed_lo;           // m/s
  float speed_hi;
  float spray_density;      // rho / rho0
  float bubble_density;
  float spray_drag;         // 1/s
  float bubble_buoyancy;    // times -gravity
  float bubble_drag;        // 1/s
  float spawn_radius;       // m: new ones start within this of their liquid particle
};

// The mesh passes' push constants (liquid/solver/mesh_field.cpp, shaders/liquid/solver/mesh_raster.vert).
LIQUID_PUSH(MeshRasterPush) {
  mat4 local_to_world;     // the mesh's transform: centre + rotation * scale * vertex
  int slot;                // the mesh field's channel
  int step;                // the spread and field passes: cells between the neighbours they read
  int unused;
  float band;              // m: the field's band (the seed pass's depth scale)
  ivec4 box_min;           // the cells within the band of the mesh's bounds, [box_min, box_max) (xyz)
  ivec4 box_max;
};

// The mesh resample pass's push constants (liquid/solver/mesh_field.cpp, mesh_resample.frag).
LIQUID_PUSH(MeshResamplePush) {
  mat4 reference_from_world;  // a world point to the point of the reference placement the mesh has there
  int slot;                   // the mesh field's channel
  float band;                 // m: the field's band
  int unused0;
  int unused1;
};

// Drawing a mesh obstacle into the 3D view (liquid/render/mesh_draw.h): 128 bytes, lavapipe's limit.
LIQUID_PUSH(MeshDrawPush) {
  mat4 view_projection;
  vec4 model_rows[3];      // the mesh's transform, the first three rows of its affine matrix
  vec4 sun_direction;      // xyz toward the sun
};

#ifdef __cplusplus
}  // namespace liquid::gpu
#endif

#endif
