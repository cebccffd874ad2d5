#!/bin/sh
# bad_model_first.sh PENUMBRA MODEL SCRATCH
# Issue 26 B13: `render --frames --model BAD` and `bench cache --model BAD` read
# the model before the GL context and the output directory: exit 2 with one
# line naming the model, no directory left — with a context or without one
# (GALLIUM_DRIVER=nonexistent makes every backend fail).
set -u
penumbra=$1 model=$2 scratch=$3
fail() { printf 'bad_model_first: %s\n' "$1"; exit 1; }
rm -rf "$scratch"
for env in "" "GALLIUM_DRIVER=nonexistent"; do
  for cmd in "render --frames 2 --model $model --out $scratch" "bench cache --model $model --sizes 64 --frames 2"; do
    # shellcheck disable=SC2086  # the words of the command
    out=$(env $env "$penumbra" $cmd 2>&1)
    status=$?
    printf '%s\n' "$out"
    [ "$status" -eq 2 ] || fail "$env $cmd: expected exit 2, got $status"
    [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "$env $cmd: expected one line"
    printf '%s\n' "$out" | grep -q "^penumbra: error: model '.*too_small.obj'" || fail "$env $cmd: the line does not name the model"
    [ -e "$scratch" ] && fail "$env $cmd: left $scratch behind"
  done
done
echo "bad_model_first: ok"
