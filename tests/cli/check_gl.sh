#!/bin/sh
# check_gl.sh PENUMBRA BACKEND GLSL_DIR SCRATCH
# `penumbra check blur --backend BACKEND` passes on the library, and fails with
# a where / expected / observed line on a copy with one wrong blur weight.
# Exit 77 (skipped) when the backend gives no context.
set -u
penumbra=$1 backend=$2 glsl=$3 scratch=$4
"$penumbra" info --backend "$backend" >/dev/null 2>"$scratch.err"
case $? in
  0) ;;
  3) echo "SKIPPED: $(cat "$scratch.err")"; exit 77 ;;
  *) cat "$scratch.err"; exit 1 ;;
esac
"$penumbra" check blur --backend "$backend" || { echo "check failed on the library's modules"; exit 1; }
rm -rf "$scratch" && cp -r "$glsl" "$scratch" || exit 1
sed -i 's/return exp(-0.5 \* t \* t);/return exp(-0.45 * t * t);/' "$scratch/blur.glsl"
grep -q 'exp(-0.45' "$scratch/blur.glsl" || { echo "could not break the weight in the copy"; exit 1; }
out=$("$penumbra" check blur --backend "$backend" --glsl-root "$scratch")
status=$?
printf '%s\n' "$out"
[ "$status" -eq 1 ] || { echo "expected exit 1 on the broken copy, got $status"; exit 1; }
printf '%s\n' "$out" | grep -Eq 'blur: FAIL .* at \([0-9]+, [0-9]+\): expected [-0-9.e]+, observed [-0-9.e]+' ||
  { echo "no where / expected / observed line"; exit 1; }
