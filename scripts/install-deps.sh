#!/bin/sh
# Installs the Debian 12 packages penumbra builds and runs with, when missing.
# Needs root (or sudo) only when something is missing.
set -eu

packages="
  cmake g++ make
  glslang-dev glslang-tools spirv-tools
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
  libglm-dev catch2 libcli11-dev nlohmann-json3-dev libstb-dev
  python3 python3-glad python3-skimage python3-matplotlib
  libembree-dev libassimp-dev assimp-testmodels fonts-dejavu-core
  clang libfuzzer-14-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  spirv-cross libspirv-cross-c-shared-dev
"

missing=""
for p in $packages; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
[ -z "$missing" ] && exit 0

echo "penumbra: installing missing Debian packages:$missing"
as_root=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "penumbra: error: need root or sudo to install:$missing" >&2; exit 1; }
  as_root="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update -q
# shellcheck disable=SC2086
$as_root apt-get install -y -q --no-install-recommends $missing
