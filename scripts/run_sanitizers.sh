#!/usr/bin/env bash
# CI's second half (.ci/run runs it after scripts/run_tests.sh): the CPU and tool tests built with
# AddressSanitizer and UndefinedBehaviorSanitizer (preset "sanitize"; a report fails the test),
# then the scene parser under libFuzzer for RASTERLIQUIDS_FUZZ_SECONDS (default 60; its older name
# LIQUID_FUZZ_SECONDS works too) from the shipped scenes (preset "fuzz", built with clang). Installs clang if it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh fuzz
cmake --preset sanitize
# What those tests run (the CPU tests and every tool), not the GPU tests: CI's time.
cmake --build --preset sanitize --target cpu_tests tools/all
ctest --preset sanitize -R '^(cpu|tool):'
cmake --preset fuzz -DRASTERLIQUIDS_FUZZ_SECONDS="${RASTERLIQUIDS_FUZZ_SECONDS:-${LIQUID_FUZZ_SECONDS:-60}}"
cmake --build --preset fuzz
ctest --preset fuzz
