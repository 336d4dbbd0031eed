#!/usr/bin/env bash
# The cost of mesh obstacles (liquid/solver/mesh_field.h) against a whole 3D step: the paper's 3D
# scene (assets/scenes/paper_3d.json, ~90k particles after its first steps) at 64^3 and 96^3 with a
# torus of 768 triangles (assets/scenes/meshes/torus.obj), and at 96^3 with one of 10,000, in its
# pool. Each is run with the torus moving (its field made again every step: the reference field's
# resample, liquid.mesh_resample) and standing still (made once), and the scene once without it:
# moving - still is the per-step cost of a moving mesh, still - none what sampling the field costs
# the grid and particle passes. Prints liquid_run's median wall time per step and GPU time per pass
# (liquid.mesh_inside, _seed, _spread and _reference are the one voxelization of the mesh into its
# reference field, in the first step, so their medians are single runs; liquid.mesh_spread's is one
# of its passes, of which there are log2 of the band's reach: 2 at the default band).
# Usage: tools/mesh_voxelization_cost.sh [BUILD_DIR] [STEPS]   (figures: docs/lavapipe-performance.md)
set -euo pipefail
build=${1:-build}
steps=${2:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$root/assets/scenes/meshes/torus.obj" "$work/torus768.obj"
python3 "$root/tools/make_torus_obj.py" "$work/torus10k.obj" 0.1 0.035 100 50
run() {  # grid, mesh (or none), speed (m/s)
  python3 - "$root/assets/scenes/paper_3d.json" "$work/scene.json" "$1" "$2" "$3" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["grid_resolution"] = int(sys.argv[3])
if sys.argv[4] != "none":
    scene["obstacles"].append({"shape": "mesh", "file": sys.argv[4] + ".obj", "center": [0.3, 0.1, 0.6],
                               "rotation": [90, 0, 0], "scale": 1.5, "velocity": [float(sys.argv[5]), 0, 0]})
json.dump(scene, open(sys.argv[2], "w"))
PY
  echo "== ${1}^3, $2, moving at $3 m/s"
  "$root/$build/bin/liquid_run" "$work/scene.json" -n "$steps" -r "$steps" | grep -E "median"
}
for grid in 64 96; do
  run "$grid" none 0
  run "$grid" torus768 0
  run "$grid" torus768 0.5
done
run 96 torus10k 0
run 96 torus10k 0.5
