#!/bin/sh
# register_plan_refusals.sh PENUMBRA SCRATCH
# Issue 53: each bad --register-shift / --register-space (bundle, check) exits 2 with one line
# `penumbra: error: …` naming the option, before anything is written (bundle -o leaves no file).
set -u
penumbra=$1 scratch=$2
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
failures=0
# refused EXPECTED ARGS...: the command exits 2, one line matching EXPECTED, no $scratch/out.hlsl.
refused() {
  expected=$1; shift
  out=$("$@" 2>&1); status=$?
  if [ "$status" -ne 2 ] || [ "$(printf '%s\n' "$out" | wc -l)" -ne 1 ] ||
     ! printf '%s\n' "$out" | grep -qF -- "penumbra: error: $expected" || [ -e "$scratch/out.hlsl" ]; then
    printf 'FAIL %s: exit %s, %s%s\n' "$*" "$status" "$out" "$([ -e "$scratch/out.hlsl" ] && echo ' (and it wrote out.hlsl)')"
    failures=$((failures + 1)); rm -f "$scratch/out.hlsl"
  fi
}
o="-o $scratch/out.hlsl"
refused "--register-shift 'x=1': 'x=1': expected KIND=N" $penumbra bundle pcf.glsl --target hlsl --register-shift x=1 $o
refused "--register-shift 't=1,t=2': t twice" $penumbra bundle pcf.glsl --target hlsl --register-shift t=1,t=2 $o
refused "--register-shift 't=': 't=': expected" $penumbra bundle pcf.glsl --target hlsl --register-shift t= $o
refused "--register-shift 't=4097': 't=4097': expected" $penumbra bundle pcf.glsl --target hlsl --register-shift t=4097 $o
refused "--register-shift 't=1,,u=2': '': expected" $penumbra bundle pcf.glsl --target hlsl --register-shift t=1,,u=2 $o
refused "--register-space 32: expected a space from 0 to 31" $penumbra bundle pcf.glsl --target hlsl --shader-model 6.0 --register-space 32 $o
refused "--register-space -1: expected a space from 0 to 31" $penumbra bundle pcf.glsl --target hlsl --shader-model 6.0 --register-space -1 $o
refused "--register-space 1: shader model 5.0 has no register spaces: expected --shader-model 5.1 or 6.0" \
  $penumbra bundle pcf.glsl --target hlsl --register-space 1 $o
refused "--register-shift: applies to --target hlsl only" $penumbra bundle pcf.glsl --target msl --register-shift t=1 $o
refused "--register-space: applies to --target hlsl only" $penumbra bundle pcf.glsl --register-space 0 $o
refused "--register-shift: applies to --target hlsl only" $penumbra bundle passes/blur.comp --interface --register-shift t=1
refused "--register-shift: applies to --api hlsl only" $penumbra check pcf --api vulkan --register-shift t=1
refused "--register-space: applies to --api hlsl only" $penumbra check pcf --register-space 1
refused "--register-shift 'q=2': 'q=2': expected" $penumbra check pcf --api hlsl --register-shift q=2
[ "$failures" -eq 0 ] || exit 1
rm -rf "$scratch"
echo "register plan refusals: 14 one-line refusals, nothing written"
