// The specialization constants the shaders declare (shaders/liquid/common.glsl) against the ids the
// host fills in (liquid/specialization.h): read back from the embedded SPIR-V (OpName + SpecId), so
// a constant renumbered on one side only fails here instead of silently feeding a wrong value.
#include "embedded_shaders.h"
#include "liquid/specialization.h"

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

std::map<std::string, uint32_t> expected_ids() {
  namespace id = liquid::specialization_id;
  std::map<std::string, uint32_t> ids{{"OBSTACLE_COUNT", id::obstacle_count},
                                      {"SHALLOW_WATER", id::shallow_water},
                                      {"INTEGER_GAMMA", id::integer_gamma},
                                      {"HAS_EMITTERS", id::has_emitters},
                                      {"GROUND_HILLS", id::ground_hills}};
  for (int i = 0; i < liquid::gpu::k_max_obstacles; ++i)
    ids["OBSTACLE_KIND_" + std::to_string(i)] = uint32_t(id::first_obstacle_kind + size_t(i));
  return ids;
}

}  // namespace

TEST_CASE("shaders declare the specialization ids the host fills in", "[shaders]") {
  const std::map<std::string, uint32_t> expected = expected_ids();
  REQUIRE(expected.size() == liquid::specialization_id::count);
  const std::map<std::string, std::span<const uint32_t>> modules{
      {"grid 2D", shaders::liquid_grid_frag_2d},         {"grid 3D", shaders::liquid_grid_frag_3d},
      {"particle 2D", shaders::liquid_particle_frag_2d}, {"particle 3D", shaders::liquid_particle_frag_3d},
      {"splat 2D", shaders::liquid_splat_vert_2d},       {"splat 3D", shaders::liquid_splat_vert_3d},
      {"raymarch", shaders::raymarch_frag},              {"2D view", shaders::view2d_frag},
      {"height field", shaders::height_field_vert}};
  for (const auto& [name, spirv] : modules) {
    INFO(name);
    const std::map<std::string, uint32_t> found = specialization_ids(spirv);
    // Each module declares all of them (they come from one include) and each with the host's id.
    CHECK(found == expected);
  }
}
