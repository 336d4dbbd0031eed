// What the host and the shaders must agree on, read back from the embedded SPIR-V: the
// specialization ids the shaders declare (shaders/liquid/common.glsl) against the ids the host fills
// in (liquid/solver/specialization.h), and the std140 offsets glslang gave the uniform block of
// shaders/liquid/shared.h against the C++ struct's. A mismatch fails here instead of silently
// feeding a wrong value.
#include "liquid/solver/gpu_types.h"
#include "liquid/solver/specialization.h"
#include "liquid_shaders.h"
#include "shaders/liquid/render/view_blocks.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <cstring>

namespace {

// name -> SpecId of every specialization constant in a SPIR-V module (names need OpName, which
// glslang emits unless told to strip).
std::map<std::string, uint32_t> specialization_ids(std::span<const uint32_t> spirv) {
  constexpr uint32_t k_op_name = 5, k_op_decorate = 71, k_decoration_spec_id = 1;
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> spec_ids;
  REQUIRE(spirv.size() > 5);
  for (size_t at = 5; at < spirv.size();) {
    const uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
    if (words == 0 || at + words > spirv.size()) FAIL("malformed SPIR-V at word " << at);
    if (opcode == k_op_name && words > 2) {
      const char* text = reinterpret_cast<const char*>(&spirv[at + 2]);
      names[spirv[at + 1]] = std::string(text, strnlen(text, (words - 2) * sizeof(uint32_t)));
    } else if (opcode == k_op_decorate && words == 4 && spirv[at + 2] == k_decoration_spec_id) {
      spec_ids[spirv[at + 1]] = spirv[at + 3];
    }
    at += words;
  }
  std::map<std::string, uint32_t> out;
  for (const auto& [id, spec] : spec_ids) out[names.count(id) ? names[id] : "?" + std::to_string(id)] = spec;
  return out;
}

// "Struct.member" -> byte offset, and "Struct.member[]" -> array stride, of every struct in a
// module (needs OpName / OpMemberName, which glslang emits unless told to strip).
std::map<std::string, uint32_t> member_layout(std::span<const uint32_t> spirv) {
  constexpr uint32_t k_op_name = 5, k_op_member_name = 6, k_op_decorate = 71, k_op_member_decorate = 72,
                     k_op_type_array = 28, k_op_type_struct = 30;
  constexpr uint32_t k_offset = 35, k_array_stride = 6;
  auto text_at = [&](size_t at, size_t words) {
    const char* text = reinterpret_cast<const char*>(&spirv[at]);
    return std::string(text, strnlen(text, words * sizeof(uint32_t)));
  };
  std::map<uint32_t, std::string> type_names;
  std::map<std::pair<uint32_t, uint32_t>, std::string> member_names;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> offsets;
  std::map<uint32_t, uint32_t> array_strides;                     // array type -> stride
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> member_types;  // (struct, member) -> type
  for (size_t at = 5; at < spirv.size();) {
    const uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
    REQUIRE(words > 0);
    if (opcode == k_op_name && words > 2) type_names[spirv[at + 1]] = text_at(at + 2, words - 2);
    if (opcode == k_op_member_name && words > 3)
      member_names[{spirv[at + 1], spirv[at + 2]}] = text_at(at + 3, words - 3);
    if (opcode == k_op_member_decorate && words == 5 && spirv[at + 3] == k_offset)
      offsets[{spirv[at + 1], spirv[at + 2]}] = spirv[at + 4];
    if (opcode == k_op_decorate && words == 4 && spirv[at + 2] == k_array_stride) array_strides[spirv[at + 1]] = spirv[at + 3];
    if (opcode == k_op_type_struct)
      for (uint32_t m = 0; m + 2 < words; ++m) member_types[{spirv[at + 1], m}] = spirv[at + 2 + m];
    (void)k_op_type_array;
    at += words;
  }
  std::map<std::string, uint32_t> out;
  for (const auto& [key, offset] : offsets) {
    const std::string name = type_names[key.first] + "." + member_names[key];
    out[name] = offset;
    if (const auto stride = array_strides.find(member_types[key]); stride != array_strides.end())
      out[name + "[]"] = stride->second;
  }
  return out;
}

// Every member of `expected` ("Struct.member" -> offset or stride) is laid out so in `module`'s SPIR-V.
void check_layout(const std::string& module, std::span<const uint32_t> spirv,
                  const std::map<std::string, uint32_t>& expected) {
  INFO(module);
  const std::map<std::string, uint32_t> found = member_layout(spirv);
  for (const auto& [member, offset] : expected) {
    INFO(member);
    REQUIRE(found.count(member) == 1);
    CHECK(found.at(member) == offset);
  }
}

std::map<std::string, uint32_t> expected_ids() {
  namespace id = liquid::specialization_id;
  std::map<std::string, uint32_t> ids{{"OBSTACLE_COUNT", id::obstacle_count},
                                      {"SHALLOW_WATER", id::shallow_water},
                                      {"INTEGER_GAMMA", id::integer_gamma},
                                      {"HAS_EMITTERS", id::has_emitters},
                                      {"GROUND_HILLS", id::ground_hills},
                                      {"WALLS_CONTINUED", id::walls_continued}};
  for (int i = 0; i < liquid::gpu::k_max_obstacles; ++i)
    ids["OBSTACLE_KIND_" + std::to_string(i)] = uint32_t(id::first_obstacle_kind + size_t(i));
  return ids;
}

}  // namespace

TEST_CASE("shaders declare the specialization ids the host fills in", "[shaders]") {
  const std::map<std::string, uint32_t> expected = expected_ids();
  REQUIRE(expected.size() == liquid::specialization_id::count);
  const std::map<std::string, std::span<const uint32_t>> modules{
      {"grid 2D", liquid_shaders::grid_frag_2d},         {"grid 3D", liquid_shaders::grid_frag_3d},
      {"grid adjoint 2D", liquid_shaders::grid_frag_2d_splat_adjoint},
      {"grid adjoint 3D", liquid_shaders::grid_frag_3d_splat_adjoint},
      {"pressure 2D", liquid_shaders::pressure_frag_2d}, {"pressure 3D", liquid_shaders::pressure_frag_3d},
      {"potential 2D", liquid_shaders::potential_frag_2d}, {"potential 3D", liquid_shaders::potential_frag_3d},
      {"particle 2D", liquid_shaders::particle_frag_2d}, {"particle 3D", liquid_shaders::particle_frag_3d},
      {"splat 2D", liquid_shaders::splat_vert_2d},       {"splat 3D", liquid_shaders::splat_vert_3d},
      {"grid 3D atlas", liquid_shaders::grid_frag_3d_atlas},
      {"grid adjoint 3D atlas", liquid_shaders::grid_frag_3d_atlas_splat_adjoint},
      {"pressure 3D atlas", liquid_shaders::pressure_frag_3d_atlas},
      {"potential 3D atlas", liquid_shaders::potential_frag_3d_atlas},
      {"particle 3D atlas", liquid_shaders::particle_frag_3d_atlas},
      {"splat 3D atlas", liquid_shaders::splat_vert_3d_atlas}, {"splat 3D geometry", liquid_shaders::splat_vert_3d_gs},
      {"raymarch atlas", liquid_shaders::raymarch_frag_atlas},
      {"raymarch", liquid_shaders::raymarch_frag},       {"2D view", liquid_shaders::view2d_frag},
      {"height field", liquid_shaders::height_field_vert}};
  for (const auto& [name, spirv] : modules) {
    INFO(name);
    std::map<std::string, uint32_t> found = specialization_ids(spirv);
    // The raymarch has three of its own after the scene's (liquid/render/raymarch.cpp checks the id).
    if (name == "raymarch" || name == "raymarch atlas") {
      CHECK(found["COMPOSITE"] == uint32_t(LIQUID_RAYMARCH_COMPOSITE_ID));
      CHECK(found["BACKGROUND_ONLY"] == uint32_t(LIQUID_RAYMARCH_BACKGROUND_ONLY_ID));
      CHECK(found["OUTPUT_ENCODING"] == uint32_t(LIQUID_RAYMARCH_OUTPUT_ID));
      found.erase("COMPOSITE");
      found.erase("BACKGROUND_ONLY");
      found.erase("OUTPUT_ENCODING");
    }
    // The particle pass has one of its own (liquid/solver/particle_update.cpp checks the id).
    if (name.starts_with("particle")) {
      CHECK(found["POSITION_CORRECTION"] == uint32_t(LIQUID_PARTICLE_POSITION_CORRECTION_ID));
      found.erase("POSITION_CORRECTION");
    }
    // The 2D view has one of its own (liquid/render/view2d.cpp checks the id).
    if (name == "2D view") {
      CHECK(found["PANEL"] == uint32_t(LIQUID_VIEW2D_PANEL_ID));
      found.erase("PANEL");
    }
    // Each module declares all of them (they come from one include) and each with the host's id.
    CHECK(found == expected);
  }
}

TEST_CASE("the solver's uniform block has the same layout in C++ and in every shader", "[shaders]") {
  using namespace liquid::gpu;
#define MEMBER(type, field) {#type "." #field, uint32_t(offsetof(type, field))}
  const std::map<std::string, uint32_t> expected{
#define SCALAR(type, field) MEMBER(SolverUniforms, field),
      LIQUID_SOLVER_SCALARS(SCALAR)
#undef SCALAR
      MEMBER(SolverUniforms, wall_kernel_beyond),
      MEMBER(SolverUniforms, obstacles), MEMBER(SolverUniforms, balls), MEMBER(SolverUniforms, ground),
      MEMBER(SolverUniforms, brushes), MEMBER(SolverUniforms, emitters), MEMBER(SolverUniforms, bodies), MEMBER(SolverUniforms, body_kernel_beyond),
      {"SolverUniforms.bodies[]", uint32_t(sizeof(Body))}, MEMBER(Obstacle, orientation),
      MEMBER(Obstacle, angular_velocity), MEMBER(Body, inertia), MEMBER(Body, mass), MEMBER(Body, external_force),
      MEMBER(Body, added_mass), MEMBER(Body, external_torque), MEMBER(Body, added_inertia_ratio),
      {"SolverUniforms.wall_kernel_beyond[]", 16}, {"SolverUniforms.body_kernel_beyond[]", 16}, {"SolverUniforms.obstacles[]", uint32_t(sizeof(Obstacle))},
      {"SolverUniforms.balls[]", 16}, {"SolverUniforms.ground[]", 16},
      {"SolverUniforms.brushes[]", uint32_t(sizeof(Brush))}, {"SolverUniforms.emitters[]", uint32_t(sizeof(EmitterRange))},
      MEMBER(Obstacle, center), MEMBER(Obstacle, sphere_radius), MEMBER(Obstacle, box_half_extent),
      MEMBER(Obstacle, metaball_threshold), MEMBER(Obstacle, velocity), MEMBER(Obstacle, first_ball),
      MEMBER(Obstacle, ball_count), MEMBER(Brush, position), MEMBER(Brush, radius), MEMBER(Brush, acceleration),
      MEMBER(EmitterRange, position), MEMBER(EmitterRange, radius), MEMBER(EmitterRange, velocity),
      MEMBER(EmitterRange, first), MEMBER(EmitterRange, end)};
#undef MEMBER
  // Modules whose shaders read obstacles, brushes and emitters, so glslang lays out every struct.
  const std::map<std::string, std::span<const uint32_t>> modules{
      {"grid 3D", liquid_shaders::grid_frag_3d}, {"particle 2D", liquid_shaders::particle_frag_2d},
      {"particle 3D", liquid_shaders::particle_frag_3d}, {"splat 3D", liquid_shaders::splat_vert_3d},
      {"grid 3D atlas", liquid_shaders::grid_frag_3d_atlas}, {"particle 3D atlas", liquid_shaders::particle_frag_3d_atlas},
      {"splat 3D atlas", liquid_shaders::splat_vert_3d_atlas}, {"splat 3D geometry", liquid_shaders::splat_vert_3d_gs}};
  for (const auto& [module, spirv] : modules) check_layout(module, spirv, expected);
}

TEST_CASE("the views' uniform and push-constant blocks have the same layout in C++ and GLSL", "[shaders]") {
  using namespace liquid::gpu;
#define MEMBER(type, field) {#type "." #field, uint32_t(offsetof(type, field))}
  const std::map<std::string, std::map<std::string, uint32_t>> expected{
      {"raymarch",
       {MEMBER(RaymarchUniforms, inverse_view_projection), MEMBER(RaymarchUniforms, view_projection),
        MEMBER(RaymarchUniforms, iso_level), MEMBER(RaymarchUniforms, sun_direction),
        MEMBER(RaymarchUniforms, fine_step_cells), MEMBER(RaymarchUniforms, bricks),
        MEMBER(RaymarchUniforms, brick_cells), MEMBER(RaymarchUniforms, brick_columns),
        MEMBER(RaymarchUniforms, brick_rows), MEMBER(RaymarchUniforms, near_depth),
        MEMBER(RaymarchUniforms, exposure), MEMBER(RaymarchUniforms, viewport_x),
        MEMBER(RaymarchUniforms, viewport_y), MEMBER(RaymarchUniforms, viewport_width),
        MEMBER(RaymarchUniforms, viewport_height), MEMBER(RaymarchUniforms, coarse_width),
        MEMBER(RaymarchUniforms, coarse_height)}},
      {"raymarch tiles", {MEMBER(RaymarchUniforms, tiles_x), MEMBER(RaymarchUniforms, tiles_y)}},
      {"raymarch atlas", {MEMBER(RaymarchUniforms, brick_columns), MEMBER(RaymarchUniforms, brick_rows)}},
      {"occupancy", {MEMBER(OccupancyPush, brick_cells)}},
      {"occupancy atlas",
       {MEMBER(OccupancyPush, grid_cells), MEMBER(OccupancyPush, brick_cells), MEMBER(OccupancyPush, bricks),
        MEMBER(OccupancyPush, grid_columns), MEMBER(OccupancyPush, grid_rows), MEMBER(OccupancyPush, brick_columns),
        MEMBER(OccupancyPush, brick_rows)}},
      {"height field",
       {MEMBER(HeightFieldUniforms, view_projection), MEMBER(HeightFieldUniforms, camera_position),
        MEMBER(HeightFieldUniforms, rest_depth), MEMBER(HeightFieldUniforms, vertical_scale),
        MEMBER(HeightFieldUniforms, skirt_base), MEMBER(HeightFieldPush, layer)}},
      {"height field fragment",
       {MEMBER(HeightFieldUniforms, camera_position), MEMBER(HeightFieldUniforms, rest_depth),
        MEMBER(HeightFieldUniforms, sun_direction), MEMBER(HeightFieldUniforms, dry_threshold)}},
      {"2D view",
       {MEMBER(View2dPush, origin), MEMBER(View2dPush, pixels_per_metre), MEMBER(View2dPush, iso_level),
        MEMBER(View2dPush, frame), MEMBER(View2dPush, wall_pixels), MEMBER(View2dPush, depth_cells)}},
      {"2D particles",
       {MEMBER(Particles2dPush, origin), MEMBER(Particles2dPush, pixels_per_metre), MEMBER(Particles2dPush, point_size),
        MEMBER(Particles2dPush, frame), MEMBER(Particles2dPush, texture_width)}}};
#undef MEMBER
  const std::map<std::string, std::span<const uint32_t>> modules{
      {"raymarch", liquid_shaders::raymarch_frag},           {"occupancy", liquid_shaders::occupancy_frag},
      {"raymarch atlas", liquid_shaders::raymarch_frag_atlas}, {"occupancy atlas", liquid_shaders::occupancy_frag_atlas},
      {"raymarch tiles", liquid_shaders::raymarch_tile_vert},
      {"height field", liquid_shaders::height_field_vert},   {"height field fragment", liquid_shaders::height_field_frag},
      {"2D view", liquid_shaders::view2d_frag},              {"2D particles", liquid_shaders::particles2d_vert}};
  for (const auto& [module, members] : expected) check_layout(module, modules.at(module), members);
}
