#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite
# (CPU tests, and GPU tests on lavapipe with validation on). CI calls exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset default
cmake --build --preset default
ctest --preset default
