#!/usr/bin/env bash
# The cost of voxelizing a moving mesh obstacle (liquid/solver/mesh_field.h) against a whole 3D step:
# the paper's 3D scene (assets/scenes/paper_3d.json, 125k particles once its jet has run) at 64^3 and
# 96^3 with a torus of 768 triangles (assets/scenes/meshes/torus.obj) moving through its pool, and at
# 96^3 with a torus of 10,000 triangles. Prints liquid_run's median GPU time of each pass; the three
# liquid.mesh_* passes are one voxelization, redone every step because the mesh moves.
# Usage: tools/mesh_voxelization_cost.sh [BUILD_DIR] [STEPS]   (docs/lavapipe-performance.md has the figures)
set -euo pipefail
build=${1:-build}
steps=${2:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$root/assets/scenes/meshes/torus.obj" "$work/torus768.obj"
python3 "$root/tools/make_torus_obj.py" "$work/torus10k.obj" 0.1 0.035 100 50
for run in "64 torus768" "96 torus768" "96 torus10k"; do
  set -- $run
  python3 - "$root/assets/scenes/paper_3d.json" "$work/scene_$1_$2.json" "$1" "$2.obj" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["grid_resolution"] = int(sys.argv[3])
scene["obstacles"].append({"shape": "mesh", "file": sys.argv[4], "center": [0.3, 0.1, 0.6], "rotation": [90, 0, 0],
                           "scale": 1.5, "velocity": [0.5, 0, 0]})
json.dump(scene, open(sys.argv[2], "w"))
PY
  echo "== ${1}^3, $2"
  "$root/$build/bin/liquid_run" "$work/scene_$1_$2.json" -n "$steps" -r "$steps" | grep -E "^scene|median"
done
