// Test main: runs Catch2, then fails the run if the validation layer said anything that a test
// did not expect and reset, so no validation message can slip through a passing test.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "tests/support/gpu.h"

#include <cstdio>

int main(int argc, char* argv[]) {
  const int failures = Catch::Session().run(argc, argv);
  const uint32_t messages = test::total_validation_messages();
  test::release_contexts();
  if (messages > 0) {
    std::fprintf(stderr, "FAILED: %u validation message(s) during the run\n", messages);
    return 1;
  }
  return failures;
}
