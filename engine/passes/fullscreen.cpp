#include "engine/passes/fullscreen.h"

#include "engine_shaders.h"

namespace engine::passes {

std::span<const uint32_t> fullscreen_vertex_shader() { return engine_shaders::fullscreen_vert; }
std::span<const uint32_t> fullscreen_layered_vertex_shader() { return engine_shaders::fullscreen_layered_vert; }
std::span<const uint32_t> fullscreen_layered_geometry_shader() { return engine_shaders::fullscreen_layered_geom; }
std::span<const uint32_t> fullscreen_vertex_layer_shader() { return engine_shaders::fullscreen_vertex_layer_vert; }

void draw_fullscreen(VkCommandBuffer cmd, uint32_t layers) { vkCmdDraw(cmd, 3, layers, 0, 0); }

}  // namespace engine::passes
