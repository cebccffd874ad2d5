#!/bin/sh
# render_truncated_model.sh PENUMBRA MODEL WORKDIR
# The first half of MODEL is refused by `penumbra render --model` with one
# line naming the file, exit 2, and nothing written: no output directory.
penumbra=$1 model=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
size=$(wc -c < "$model")
head -c $((size / 2)) "$model" > "$work/truncated.glb"
out=$("$penumbra" render --model "$work/truncated.glb" --map-size 64 --screen 32 --out "$work/out" 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" -eq 2 ] || { echo "expected exit 2, got $status"; exit 1; }
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || { echo "expected one line"; exit 1; }
printf '%s\n' "$out" | grep -Eq "^penumbra: error: model '.*truncated.glb': not a mesh file Assimp can read" ||
  { echo "unexpected message"; exit 1; }
[ ! -e "$work/out" ] || { echo "the output directory was created"; exit 1; }
