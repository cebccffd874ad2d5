#!/bin/sh
# check_gl.sh PENUMBRA BACKEND MODULE GLSL_DIR SCRATCH FILE FROM TO
# `penumbra check MODULE --backend BACKEND` passes on the library, and fails
# with a where / expected / observed line on a copy of GLSL_DIR in which FILE
# has its first FROM replaced by TO (a deliberate mistake).
# BACKEND vulkan or hlsl: the same with `--api vulkan | hlsl` (the Vulkan executor). On vulkan, hlsl
# and egl-surfaceless the broken copy only: the library's run of every check is cli_check_all_gl's
# (check_all_gl.sh, EGL surfaceless) and check_vulkan.py's.
# Exit 77 (skipped) when the backend gives no context.
set -u
penumbra=$1 backend=$2 module=$3 glsl=$4 scratch=$5 file=$6
export PN_FROM="$7" PN_TO="$8"
case $backend in
  vulkan|hlsl) info="--api vulkan" where="--api $backend" ;;
  *) info="--backend $backend" where="--backend $backend" ;;
esac
# shellcheck disable=SC2086  # $info and $where are two words each
"$penumbra" info $info >/dev/null 2>"$scratch.err"
case $? in
  0) ;;
  3) echo "SKIPPED: $(cat "$scratch.err")"; exit 77 ;;
  *) cat "$scratch.err"; exit 1 ;;
esac
# On the library's modules (but where cli_check_all_gl and cli_check_{vulkan,hlsl}_vs_gl run them).
# shellcheck disable=SC2086
case $backend in
  vulkan|hlsl|egl-surfaceless) ;;
  *) "$penumbra" check "$module" $where || { echo "check failed on the library's modules"; exit 1; } ;;
esac
rm -rf "$scratch" && cp -r "$glsl" "$scratch" || exit 1
perl -0pi -e 's/\Q$ENV{PN_FROM}\E/$ENV{PN_TO}/' "$scratch/$file"
grep -qF -- "$PN_TO" "$scratch/$file" || { echo "could not put the mistake into $file"; exit 1; }
# shellcheck disable=SC2086
# --quick: every program on fewer fixtures (docs/reliability.md); each mistake shows there too.
out=$("$penumbra" check "$module" $where --quick --glsl-root "$scratch")
status=$?
rm -rf "$scratch"
printf '%s\n' "$out"
[ "$status" -eq 1 ] || { echo "expected exit 1 on the broken copy, got $status"; exit 1; }
printf '%s\n' "$out" | grep -Eq "$module: FAIL .* at \([0-9]+, [0-9]+\)(\[[0-9]\])?: expected [-+0-9.einf]+, observed [-+0-9.einf]+" ||
  { echo "no where / expected / observed line"; exit 1; }
