#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job: the 3D dam break
# rendered to PNG frames (raymarch + FXAA at 1024x768) in frames/dam_break_3d/, with stats.csv.
# Extra arguments go to liquid_capture (for example --frames 60 or --export-particles).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset default
cmake --build --preset default
./build/bin/liquid_capture assets/scenes/dam_break_3d.json --frames 16 --out frames/dam_break_3d "$@"
