#!/bin/sh
# Configures and builds penumbra into build/ (or $PENUMBRA_BUILD_DIR).
# Arguments are passed on to the configure step (e.g. -DPENUMBRA_SANITIZE=ON);
# $PENUMBRA_BUILD_TARGETS, when set, names the targets to build instead of all.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PENUMBRA_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@"
# shellcheck disable=SC2086  # target names, split on spaces
cmake --build "$build" -j "$(nproc)" ${PENUMBRA_BUILD_TARGETS:+--target $PENUMBRA_BUILD_TARGETS}
