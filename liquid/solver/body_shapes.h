// The dynamic mesh obstacles' signed distance in their own frames: one 3D texture (RGBA32F, a
// channel per dynamic mesh in scene order, at most four), made once when the node is created, each
// channel a cube about the body's centre of mass spanning its mesh and a margin past the kernel's
// reach, at half a cell. Each cube is voxelized by the rasterizer as the static meshes are
// (liquid/solver/mesh_field.h: the mesh alone, unturned, at the centre of a grid of the cube's
// cells on the node's 3D path), then copied into its channel: exact within the seed band of the
// surface, the jump flood's distance beyond, clamped a cell past the node's kernel. The passes that
// evaluate dynamic obstacles (LIQUID_BODIES: grid, pressure, particle, body force and exchange)
// sample it at the body's pose read from the body-state texture, where an analytic body evaluates
// its distance (body_mesh_distance in common.glsl), so a turning, moving body needs no voxelization
// and no pose from the host, on every 3D path. Past its cube the distance is the cube's value plus
// the distance to the cube (beyond any reach that matters).
#pragma once

#include "engine/passes/bindings.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/sampler.h"
#include "liquid/physics/setup.h"
#include "liquid/scene.h"
#include "liquid/solver/images.h"
#include "liquid/types.h"

#include <glm/glm.hpp>

#include <vector>

namespace liquid {

constexpr VkFormat k_body_shapes_format = VK_FORMAT_R32G32B32A32_SFLOAT;

// Whether obstacle `o` is a dynamic mesh (a body whose distance is in the body-shape texture).
bool is_mesh_body(const Obstacle& o);

// The texture's texels per side: the largest cube at half a cell, at most 128; 1 without dynamic meshes.
int body_shape_resolution(const Scene& scene, const SimulationSetup& setup);

// The texture, texel (x, y, z) at the centre of cell (x, y, z) of each cube: channel k the k-th
// dynamic mesh's distance (m, negative inside), the other channels far; 1 x 1 x 1 and far without
// dynamic meshes (the passes bind it either way). Voxelized on `path`, blocking (at node creation).
engine::vk::Image make_body_shapes(engine::vk::Context& context, const Scene& scene, const SimulationSetup& setup,
                                   GridPath path);

// For the passes that read the body state: the pipeline's binding (LIQUID_BINDING_BODY_SHAPES in
// `stages`) and the pass's read of the texture, linearly filtered.
void add_body_shapes_binding(std::vector<engine::vk::DescriptorBinding>& bindings, VkShaderStageFlags stages);
void bind_body_shapes(engine::passes::PassBindings& bindings, PassBuilder& builder, ImageHandle shapes,
                      const engine::vk::Sampler& linear);

}  // namespace liquid
