#!/bin/sh
# check_es310.sh PENUMBRA GLSL_DIR SCRATCH
# `penumbra check --api es310 --quick` runs every registered module check on an OpenGL ES 3.1
# context (every program, on fewer fixtures than GL 4.5's run: docs/reliability.md) and every module passes; and a copy of GLSL_DIR with one mistake in blur.glsl fails
# there with a where / expected / observed line (the checks still see errors on ES).
# Exit 77 (skipped) when no ES 3.1 context can be made (penumbra's exit code 3).
set -u
penumbra=$1 glsl=$2 scratch=$3
"$penumbra" info --api es310 >/dev/null 2>"$scratch.err"
case $? in
  0) ;;
  3) echo "SKIPPED: $(cat "$scratch.err")"; exit 77 ;;
  *) cat "$scratch.err"; exit 1 ;;
esac
# The registered modules, from the message that refuses an unknown one.
modules=$("$penumbra" check no-such-module 2>&1 | sed -n 's/.*expected one of //p' | tr -d ',')
[ -n "$modules" ] || { echo "could not list the registered modules"; exit 1; }
out=$("$penumbra" check --api es310 --quick 2>&1)
status=$?
printf '%s\n' "$out"
printf '%s\n' "$out" | grep -Eq "^backend .*OpenGL ES 3\.[1-9]" || { echo "not run on an OpenGL ES 3.1+ context"; exit 1; }
for m in $modules; do
  printf '%s\n' "$out" | grep -Eq "^$m +[0-9]+ .* pass$" || { echo "module $m did not pass on ES"; exit 1; }
done
[ "$status" -eq 0 ] || { echo "expected exit 0, got $status"; exit 1; }
rm -rf "$scratch" && cp -r "$glsl" "$scratch" || exit 1
perl -0pi -e 's/\Qreturn exp(-0.5 * t * t)\E/return exp(-0.45 * t * t)/' "$scratch/blur.glsl"
grep -qF -- "exp(-0.45 * t * t)" "$scratch/blur.glsl" || { echo "could not put the mistake into blur.glsl"; exit 1; }
out=$("$penumbra" check blur --api es310 --quick --glsl-root "$scratch" 2>&1)
status=$?
rm -rf "$scratch"
printf '%s\n' "$out" | tail -3
[ "$status" -eq 1 ] || { echo "expected exit 1 on the broken copy, got $status"; exit 1; }
printf '%s\n' "$out" | grep -Eq "blur: FAIL .* at \([0-9]+, [0-9]+\): expected [-+0-9.einf]+, observed [-+0-9.einf]+" ||
  { echo "no where / expected / observed line"; exit 1; }
