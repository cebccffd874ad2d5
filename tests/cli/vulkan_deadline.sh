#!/bin/sh
# vulkan_deadline.sh PENUMBRA GLSL_DIR WORK_DIR
# Issue 39 (5): on Vulkan a passed deadline is a verdict — `FAIL … did not finish within …`,
# exit 1 — never a signal or a hang:
# - a dispatch still running at its --gpu-timeout (a copy of blur whose endless loop only
#   llvmpipe's silent 65535-iteration cap ends, --loop-limit above it): the job is abandoned,
#   nothing it reads is freed under it, the process ends without waiting for it (it used to
#   end in SIGSEGV, or hang in the device's destruction);
# - a copy whose every dispatch stays under the deadline but whose check would run for many
#   minutes (each weight computation 60000 steps long): the check's device time is bounded by
#   10 x --gpu-timeout (it used to run past 116 s);
# - the library's traversal at 0.2 s and summed_area on hlsl at 0.1 s (the SIGSEGVs):
#   FAIL or pass, never a signal.
# Exit 77 (skipped) without a Vulkan device.
set -u
penumbra=$1 glsl=$2 work=$3
fail() { printf 'vulkan_deadline: %s\n' "$1"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
for copy in endless slow; do cp -r "$glsl" "$work/$copy" || fail "cannot copy $glsl"; done
perl -0pi -e 's/(PnBlurWeights pn_blurWeightsStart\(float sigma\) \{\n)/$1  int i = 0;\n  while (i < 10) {\n    int j = 0;\n    while (j < 10) {\n      sigma = sigma * 1.0000001 + 1e-30;\n    }\n    i++;\n  }\n/' "$work/endless/blur.glsl"
grep -q '    while (j < 10) {' "$work/endless/blur.glsl" || fail "could not put the endless loop into blur.glsl"
perl -0pi -e 's/(PnBlurWeights pn_blurWeightsStart\(float sigma\) \{\n)/$1  for (int k = 0; k < 60000; ++k) sigma = sigma * 1.0000001 + 1e-30;\n/' "$work/slow/blur.glsl"
grep -q 'k < 60000' "$work/slow/blur.glsl" || fail "could not put the slow loop into blur.glsl"

# run MODULE WANT REGEX ARGS…: exit 1 with REGEX under MODULE (WANT=1), or 1 or 0 (WANT=either),
# within 60 s, every line the report's own.
run() {
  module=$1 want=$2 regex=$3
  shift 3
  start=$(date +%s)
  out=$(timeout 60 "$penumbra" check "$module" "$@" 2>&1)
  status=$?
  seconds=$(( $(date +%s) - start ))
  [ "$status" -eq 3 ] && { echo "SKIPPED: no Vulkan device"; exit 77; }
  printf '%s\n' "$out"
  echo "($seconds s, exit $status)"
  [ "$status" -eq 124 ] && fail "check $module $*: still running after 60 s"
  [ "$status" -gt 128 ] && fail "check $module $*: ended by signal $((status - 128))"
  if [ "$want" = either ] && [ "$status" -eq 0 ]; then return; fi
  [ "$status" -eq 1 ] || fail "check $module $*: expected exit 1, got $status"
  printf '%s\n' "$out" | grep -Eq "^$module: FAIL .*$regex" || fail "check $module $*: no line '$module: FAIL …$regex'"
  printf '%s\n' "$out" | grep -Ev "^(vulkan: |hlsl |module |$module |$module: FAIL )" | grep -q . &&
    fail "check $module $*: a line that is not the report's"
  return 0
}
# (the dispatch's deadline, or the check's 10 x: which comes first depends on how long llvmpipe's
# cap lets one dispatch run)
run blur 1 'passes/blur.comp: dispatch.* did not finish within' \
  --api vulkan --glsl-root "$work/endless" --gpu-timeout 0.5 --loop-limit 1073741824
run blur 1 "did not finish within" --api vulkan --glsl-root "$work/slow" --gpu-timeout 0.5
run traversal either 'did not finish within' --api vulkan --gpu-timeout 0.2
run summed_area either 'did not finish within' --api hlsl --gpu-timeout 0.1
echo "vulkan_deadline: ok"
