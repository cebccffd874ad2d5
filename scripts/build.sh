#!/bin/sh
# Configures and builds penumbra into build/ (or $PENUMBRA_BUILD_DIR).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PENUMBRA_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" -j "$(nproc)"
