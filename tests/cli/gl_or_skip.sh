#!/bin/sh
# gl_or_skip.sh PENUMBRA REGEX ARGS...
# Runs `PENUMBRA ARGS...`; passes when it exits 0 and prints REGEX; exits 77
# (skipped) when it found no GL context (penumbra's exit code 3).
penumbra=$1 regex=$2
shift 2
out=$("$penumbra" "$@" 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" -eq 3 ] && { echo "SKIPPED: no GL context"; exit 77; }
[ "$status" -eq 0 ] || { echo "expected exit 0, got $status"; exit 1; }
printf '%s\n' "$out" | grep -Eq -- "$regex" || { echo "output does not match /$regex/"; exit 1; }
