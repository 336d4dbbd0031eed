// Helpers for full-screen passes: the embedded full-screen-triangle vertex shader and a draw.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

namespace engine::passes {

// SPIR-V of shaders/common/fullscreen.vert (v_uv at location 0).
std::span<const uint32_t> fullscreen_vertex_shader();
// SPIR-V of the layered pair: vertex + geometry routing instance i to layer i (v_layer, location 1).
std::span<const uint32_t> fullscreen_layered_vertex_shader();
std::span<const uint32_t> fullscreen_layered_geometry_shader();
// SPIR-V of the same vertex shader writing gl_Layer itself (v_layer too), for devices with
// shaderOutputLayer: layered passes with no geometry shader.
std::span<const uint32_t> fullscreen_vertex_layer_shader();

// Draws the full-screen triangle once per layer (layers = 1 for a 2D target).
void draw_fullscreen(VkCommandBuffer cmd, uint32_t layers = 1);

}  // namespace engine::passes
