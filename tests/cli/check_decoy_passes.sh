#!/bin/sh
# check_decoy_passes.sh PENUMBRA GLSL_DIR SCRATCH
# Issue 26 B2: the runner's own pass files come from the glsl root, never from
# the working directory. Run from inside a directory whose passes/blur.comp is
# a decoy, `check blur` passes on the library although the decoy is not GLSL,
# and fails on a copy whose own passes/blur.comp is broken although the decoy
# is the good file (the false PASS the probe found).
# Exit 77 (skipped) without a context.
set -u
penumbra=$1 glsl=$(cd "$2" && pwd) scratch=$3
"$penumbra" info >/dev/null 2>"$scratch.err"
case $? in
  0) ;;
  3) echo "SKIPPED: $(cat "$scratch.err")"; exit 77 ;;
  *) cat "$scratch.err"; exit 1 ;;
esac
rm -rf "$scratch" && mkdir -p "$scratch/cwd/passes" || exit 1
printf 'this is not GLSL\n' > "$scratch/cwd/passes/blur.comp"
(cd "$scratch/cwd" && "$penumbra" check blur --glsl-root "$glsl" --blur-radius 2) ||
  { echo "check failed on the library with a decoy passes/ in the working directory"; exit 1; }
cp -r "$glsl" "$scratch/root" && cp "$glsl/passes/blur.comp" "$scratch/cwd/passes/blur.comp" || exit 1
printf 'this is not GLSL\n' >> "$scratch/root/passes/blur.comp"
out=$(cd "$scratch/cwd" && "$penumbra" check blur --glsl-root "$scratch/root" --blur-radius 2 2>&1)
status=$?
rm -rf "$scratch"
printf '%s\n' "$out"
[ "$status" -ne 0 ] || { echo "false PASS: the working directory's passes/blur.comp was compiled, not the root's"; exit 1; }
printf '%s\n' "$out" | grep -q "passes/blur.comp" || { echo "the failure does not name the root's passes/blur.comp"; exit 1; }
echo "ok: the root's passes, whatever the working directory holds"
