#!/usr/bin/env bash
# Installs the Debian 12 packages Cloudscape builds and tests with, skipping those present.
# Needs root (or sudo). Nothing else is downloaded, at any time.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git
    libglm-dev libtbb-dev libopenexr-dev libstb-dev nlohmann-json3-dev libcli11-dev
    libgtest-dev libbenchmark-dev glslc
    libvulkan-dev libvulkan1 mesa-vulkan-drivers vulkan-validationlayers
    clang libclang-rt-14-dev llvm # sanitizer stage and fuzzers; llvm has llvm-symbolizer
    libglfw3-dev libimgui-dev # the viewer (cloudscape view)
    xvfb xauth # the viewer's tests run it under xvfb-run
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: run as root to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
