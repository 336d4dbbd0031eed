// The Vulkan contexts GPU tests share: lavapipe (or RASTERLIQUIDS_DEVICE) with the validation layer
// and synchronization validation on. Each GPU test ends with REQUIRE_NO_VALIDATION_MESSAGES(), and
// the test main fails the run if any message was counted at all, on any of them.
#pragma once

#include "engine/vk/context.h"

#include <catch2/catch.hpp>

namespace test {

// Created on first use; a missing device fails the calling test with the reason.
engine::vk::Context& gpu();

// The optional features that pick a way of rendering 3D grids (engine/vk/device_requirements.cpp).
struct LayerFeatures {
  bool geometry_shader = false;
  bool vertex_layer_output = false;  // shaderOutputLayer
  auto operator<=>(const LayerFeatures&) const = default;
};
// A context like gpu()'s whose device is created with exactly these of the optional features
// (whatever the device supports), so the validation layer reports any use of a disabled one.
// One per combination, created on first use.
engine::vk::Context& gpu_with(LayerFeatures features);

// Total validation messages seen by every context this process created.
uint32_t total_validation_messages();

// Destroys every context, newest first; the test main calls it before returning (the validation
// layer crashes when several of its instances are left to static destructors at exit).
void release_contexts();

}  // namespace test

#define REQUIRE_NO_VALIDATION_MESSAGES_ON(context)                                         \
  do {                                                                                     \
    INFO("last validation message: " << (context).last_validation_message());             \
    REQUIRE((context).validation_message_count() == 0u);                                   \
  } while (0)

#define REQUIRE_NO_VALIDATION_MESSAGES() REQUIRE_NO_VALIDATION_MESSAGES_ON(::test::gpu())
