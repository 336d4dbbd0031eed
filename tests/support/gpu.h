// The Vulkan context every GPU test shares: lavapipe (or LIQUID_DEVICE) with the validation layer
// and synchronization validation on. Each GPU test ends with REQUIRE_NO_VALIDATION_MESSAGES(), and
// the test main fails the run if any message was counted at all.
#pragma once

#include "engine/vk/context.h"

#include <catch2/catch.hpp>

namespace test {

// Created on first use; a missing device fails the calling test with the reason.
engine::vk::Context& gpu();

// Total validation messages seen by every context this process created.
uint32_t total_validation_messages();

}  // namespace test

#define REQUIRE_NO_VALIDATION_MESSAGES()                                                   \
  do {                                                                                     \
    INFO("last validation message: " << ::test::gpu().last_validation_message());         \
    REQUIRE(::test::gpu().validation_message_count() == 0u);                               \
  } while (0)
