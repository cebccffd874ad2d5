#!/bin/sh
# expect.sh CODE REGEX -- COMMAND...
# Passes when COMMAND exits with CODE and its output (stdout and stderr
# together) matches the extended regular expression REGEX.
code=$1 regex=$2
shift 3
out=$("$@" 2>&1)
status=$?
if [ "$status" -ne "$code" ]; then
  printf 'expected exit %s, got %s from: %s\n%s\n' "$code" "$status" "$*" "$out"
  exit 1
fi
if ! printf '%s\n' "$out" | grep -Eq -- "$regex"; then
  printf 'output of "%s" does not match /%s/:\n%s\n' "$*" "$regex" "$out"
  exit 1
fi
printf '%s\n' "$out"
