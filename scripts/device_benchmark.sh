#!/usr/bin/env bash
# The benchmark on a machine with a GPU and its Vulkan driver: builds liquid_benchmark alone
# (Release, no tests), then times the paper's configurations (both splats) and the 3D scaling set
# (125k to 1M particles) on the discrete GPU, and prints the tables against the paper's figures
# (35 fps in 3D, 296 fps in 2D on its Quadro 2000M). About 5 minutes on a workstation GPU with a
# warm build; the JSON, the output and the charts go to OUT (default out/device_benchmark).
#
#   scripts/device_benchmark.sh [OUT] [liquid_benchmark timing flags...]
#
# The timing flags replace the defaults (--runs 60 --scaling-runs 30 --warmup 10), e.g. --quick
# for a first look.
# RASTERLIQUIDS_DEVICE picks another device (default: discrete). Where the machine has no Vulkan
# loader but the project's carried .gl/ packages (docs/development.md, "A machine with a GPU"),
# they are unpacked first.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/device_benchmark}
shift || true

if ! ldconfig -p | grep 'libvulkan\.so\.1' >/dev/null; then
  if compgen -G ".gl/*.deb" >/dev/null; then
    echo "device_benchmark: no Vulkan loader; unpacking .gl/*.deb"
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
  else
    echo "device_benchmark: no Vulkan loader (libvulkan.so.1) and no .gl/*.deb to unpack" >&2
    exit 1
  fi
fi
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [[ -z "${VK_DRIVER_FILES:-}" && -f $nvidia_icd ]]; then export VK_DRIVER_FILES=$nvidia_icd; fi
export RASTERLIQUIDS_DEVICE=${RASTERLIQUIDS_DEVICE:-discrete}

start=$(date +%s)
cmake -S . -B build-device -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build build-device --target liquid_benchmark
echo "device_benchmark: built in $(($(date +%s) - start)) s"

mkdir -p "$out"
# The paper's configurations (one step per frame, as the paper times them) and the 3D scaling set;
# more timed frames than on lavapipe, since a GPU frame is short and its median needs them.
timing=(--runs 60 --scaling-runs 30 --warmup 10)
if (($#)); then timing=("$@"); fi
./build-device/bin/liquid_benchmark --only paper_ --only shallow_water --only scaling3d "${timing[@]}" \
  -o "$out/benchmark.json" | tee "$out/benchmark.txt"
if python3 -c "import matplotlib" 2>/dev/null; then
  python3 tools/liquid_benchmark/plot_benchmark.py "$out/benchmark.json" -o "$out"
fi
echo "device_benchmark: $(($(date +%s) - start)) s in all; results in $out"
