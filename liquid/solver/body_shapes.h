// The dynamic mesh obstacles' signed distance in their own frames: one 3D texture (RGBA32F, a
// channel per dynamic mesh in scene order, at most four), computed once on the CPU when the node
// is created from the closed mesh (liquid/physics/mesh.h's exact distance and winding sign), each
// channel a cube about the body's centre of mass spanning its mesh and a margin past the kernel's
// reach, at half a cell. The passes that evaluate dynamic obstacles (LIQUID_BODIES: grid, pressure,
// particle, body force and exchange) sample it at the body's pose read from the body-state texture,
// where an analytic body evaluates its distance (body_mesh_distance in common.glsl), so a turning,
// moving body needs no voxelization and no pose from the host, on every 3D path. Past its cube the
// distance is the cube's value plus the distance to the cube (beyond any reach that matters).
#pragma once

#include "engine/passes/bindings.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/images.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

constexpr VkFormat k_body_shapes_format = VK_FORMAT_R32G32B32A32_SFLOAT;

// Whether obstacle `o` is a dynamic mesh (a body whose distance is in the body-shape texture).
bool is_mesh_body(const Obstacle& o);

// The texture's texels per side: the largest cube at half a cell, at most 128; 1 without dynamic meshes.
int body_shape_resolution(const Scene& scene, const SimulationSetup& setup);

// The texels, x fastest, then y, then z: channel k the k-th dynamic mesh's distance (m, negative
// inside) at the texel centres of its cube; the other channels far.
std::vector<glm::vec4> body_shape_texels(const Scene& scene, const SimulationSetup& setup);

// The texture, uploaded (1 x 1 x 1 and far without dynamic meshes: the passes bind it either way).
engine::vk::Image make_body_shapes(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup);

// For the passes that read the body state: the pipeline's binding (LIQUID_BINDING_BODY_SHAPES in
// `stages`) and the pass's read of the texture, linearly filtered.
void add_body_shapes_binding(std::vector<engine::vk::DescriptorBinding>& bindings, VkShaderStageFlags stages);
void bind_body_shapes(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle shapes,
                      const engine::vk::Sampler& linear);

}  // namespace liquid
