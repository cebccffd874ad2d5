#!/bin/sh
# README command 1: install what is missing, build, and run the main job.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
exec "${PENUMBRA_BUILD_DIR:-$root/build}/penumbra" render "$@"
