#!/bin/sh
# one_line_error.sh REGEX -- COMMAND...
# Issue 26 B14/B15: COMMAND exits 2 with exactly one line of output, in the
# documented form `penumbra: error: ...`, matching the extended regex REGEX.
regex=$1
shift 2
out=$("$@" 2>&1)
status=$?
[ "$status" -eq 2 ] || { printf 'expected exit 2, got %s from: %s\n%s\n' "$status" "$*" "$out"; exit 1; }
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || { printf 'expected one line from: %s\n%s\n' "$*" "$out"; exit 1; }
printf '%s\n' "$out" | grep -Eq -- "^penumbra: error: .*$regex" ||
  { printf 'output of "%s" is not `penumbra: error: ...` matching /%s/:\n%s\n' "$*" "$regex" "$out"; exit 1; }
printf '%s\n' "$out"
