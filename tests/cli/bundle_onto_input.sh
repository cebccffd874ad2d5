#!/bin/sh
# bundle_onto_input.sh PENUMBRA GLSL_DIR SCRATCH
# Issue 26 B12: `bundle X -o X` (or onto a file X includes, by any path) is
# refused with exit 2 and one line, and the module is left as it was.
set -u
penumbra=$1 glsl=$2 scratch=$3
fail() { printf 'bundle_onto_input: %s\n' "$1"; exit 1; }
rm -rf "$scratch" && cp -r "$glsl" "$scratch" || fail "cannot copy $glsl"
for target in blur.glsl blur.h ./passes/../blur.glsl; do
  cp "$scratch/blur.glsl" "$scratch.before" && cp "$scratch/blur.h" "$scratch.before.h" || fail "cannot keep the originals"
  out=$("$penumbra" bundle blur.glsl --glsl-root "$scratch" -o "$scratch/$target" 2>&1)
  status=$?
  printf '%s\n' "$out"
  [ "$status" -eq 2 ] || fail "-o $target: expected exit 2, got $status"
  [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "-o $target: expected one line"
  printf '%s\n' "$out" | grep -q "one of the bundle's inputs" || fail "-o $target: the line does not say why"
  cmp -s "$scratch/blur.glsl" "$scratch.before" && cmp -s "$scratch/blur.h" "$scratch.before.h" ||
    fail "-o $target: an input was changed"
done
"$penumbra" bundle blur.glsl --glsl-root "$scratch" -o "$scratch/blur_bundle.glsl" || fail "a new output was refused"
rm -rf "$scratch" "$scratch.before" "$scratch.before.h"
echo "bundle_onto_input: ok"
