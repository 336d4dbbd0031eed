#!/usr/bin/env bash
# Installs what this project needs from Debian 12 packages, only what is missing.
# Needs root (or sudo). Safe to run again: it does nothing when everything is there.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglm-dev libstb-dev catch2 nlohmann-json3-dev libcli11-dev
  python3 python3-matplotlib  # matplotlib: the plot scripts (tools/*/plot_*.py) draw their SVGs with it
  libglfw3-dev libimgui-dev xvfb
  # The capture tool: OpenVDB volumes (Boost.Iostreams for OpenVDB's CMake module, the Python
  # module for the test that reads them back) and --video.
  libopenvdb-dev libboost-iostreams-dev python3-openvdb ffmpeg
)

# `setup.sh fuzz`: also clang and its sanitizer and libFuzzer runtimes, for scripts/run_sanitizers.sh.
if [[ "${1:-}" == fuzz ]]; then
  packages+=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all dependencies are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
