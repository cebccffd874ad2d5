#!/bin/sh
# broken_copy_commands.sh PENUMBRA GLSL_DIR WORK_DIR
# A copy of the modules whose blur.glsl does not compile:
# - `check blur region` reports blur as failing with the driver's diagnostic,
#   each line under the module's name, and still runs region (exit 1);
# - `figures` on a copy whose reuse.glsl (the sixth of seven pictures) does not
#   compile writes nothing: exit 1 and the output directory is not made.
# - `check blur` on a copy whose blur weights run a doubly nested endless loop fails
#   within its --gpu-timeout (here 20 s; the loop guard ends it long before),
#   naming the pass, the file and the line of the loop (llvmpipe used to delete
#   or cap the loop, and the check passed);
# - the same with the loop spelled where only the preprocessor sees it (issue 39): a
#   macro `#/**/define PN_REPEAT wh\⏎ile`, and a `while` that comes from an included
#   header: each fails naming the line that spells the loop (both used to pass).
# Exit 77 (skipped) without a GL context.
set -u
penumbra=$1 glsl=$2 work=$3
fail() { printf 'broken_copy_commands: %s\n' "$1"; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cp -r "$glsl" "$work/copy" || fail "cannot copy $glsl"
perl -0pi -e 's/return exp\(-0\.5 \* t \* t\);/return exp(-0.5 * t * t) +;/' "$work/copy/blur.glsl"
grep -q 'return exp(-0.5 \* t \* t) +;' "$work/copy/blur.glsl" || fail "could not break blur.glsl"

out=$("$penumbra" check blur region --glsl-root "$work/copy" 2>&1)
status=$?
[ "$status" -eq 3 ] && { echo "SKIPPED: no GL context"; exit 77; }
printf '%s\n' "$out"
[ "$status" -eq 1 ] || fail "check: expected exit 1, got $status"
printf '%s\n' "$out" | grep -Eq '^blur +0 +error: did not run +FAIL$' || fail "check: no failing blur row"
printf '%s\n' "$out" | grep -Eq '^region +[0-9]+ .* pass$' || fail "check: region did not run after blur failed"
printf '%s\n' "$out" | grep -Eq '^blur: FAIL blur\.glsl:[0-9]+: error: .*syntax error' || fail "check: no diagnostic line for blur"
printf '%s\n' "$out" | grep -Ev '^(backend |module |blur |region |blur: FAIL )' | grep -q . &&
  fail "check: a line of the report is not under a module's name"

cp "$glsl/blur.glsl" "$work/copy/blur.glsl" && printf 'float pnBroken( {\n' >> "$work/copy/reuse.glsl" ||
  fail "could not break reuse.glsl"
out=$("$penumbra" figures --glsl-root "$work/copy" --out "$work/figures" 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" -eq 1 ] || fail "figures: expected exit 1, got $status"
printf '%s\n' "$out" | grep -q "reuse.glsl" || fail "figures: the error does not name reuse.glsl"
[ -e "$work/figures" ] && fail "figures: wrote $(ls "$work/figures" | wc -l) files before failing"
cp "$glsl/reuse.glsl" "$work/copy/reuse.glsl" || fail "could not restore reuse.glsl"
perl -0pi -e 's/(PnBlurWeights pn_blurWeightsStart\(float sigma\) \{\n)/$1  int i = 0;\n  while (i < 10) {\n    int j = 0;\n    while (j < 10) {\n      sigma = sigma * 1.0000001 + 1e-30;\n    }\n    i++;\n  }\n/' "$work/copy/blur.glsl"
line=$(grep -n '    while (j < 10) {' "$work/copy/blur.glsl" | cut -d: -f1)
[ -n "$line" ] || fail "could not put the endless loop into blur.glsl"
start=$(date +%s)
out=$(timeout 120 "$penumbra" check blur --glsl-root "$work/copy" --gpu-timeout 20 2>&1)
status=$?
seconds=$(( $(date +%s) - start ))
printf '%s\n' "$out"
[ "$status" -eq 1 ] || fail "endless loop: expected exit 1, got $status after $seconds s"
[ "$seconds" -le 30 ] || fail "endless loop: took $seconds s"
printf '%s\n' "$out" | grep -q "^blur: FAIL passes/blur.comp: dispatch: the loop at blur.glsl:$line ran past 65000 iterations" ||
  fail "endless loop: no message naming the pass and blur.glsl:$line"

# Issue 39 (after issue 26 B3): an endless loop spelled through a macro, the #define itself hidden from
# a textual reader (a comment after its `#`, the keyword split by a line continuation), used to pass:
# the guard reads glslang's preprocessed text, where it is a plain loop.
cp "$glsl/blur.glsl" "$work/copy/blur.glsl" || fail "could not restore blur.glsl"
perl -0pi -e 's/(PnBlurWeights pn_blurWeightsStart\(float sigma\) \{\n)/$1#\/**\/define PN_REPEAT wh\\\nile\n  float x = 0.0;\n  PN_REPEAT (x > -1.0) {\n    x += 1.0;\n  }\n/' "$work/copy/blur.glsl"
line=$(grep -n '^  PN_REPEAT (x > -1.0) {' "$work/copy/blur.glsl" | cut -d: -f1)
grep -q '^#/\*\*/define PN_REPEAT wh\\$' "$work/copy/blur.glsl" && [ -n "$line" ] ||
  fail "could not put the macro-spelled loop into blur.glsl"
out=$(timeout 120 "$penumbra" check blur --glsl-root "$work/copy" --gpu-timeout 20 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" -eq 1 ] || fail "macro loop: expected exit 1 (a false PASS before), got $status"
printf '%s\n' "$out" | grep -q "^blur: FAIL passes/blur.comp: dispatch: the loop at blur.glsl:$line ran past" ||
  fail "macro loop: no message naming the loop at blur.glsl:$line"

# The keyword from an included header, its condition in blur.glsl: a #line marker stands between them.
cp "$glsl/blur.glsl" "$work/copy/blur.glsl" && printf '  while\n' > "$work/copy/pn_repeat.h" ||
  fail "could not restore blur.glsl"
perl -0pi -e 's/(PnBlurWeights pn_blurWeightsStart\(float sigma\) \{\n)/$1  float x = 0.0;\n#include "pn_repeat.h"\n  (x > -1.0) {\n    x += 1.0;\n  }\n/' "$work/copy/blur.glsl"
grep -q '^#include "pn_repeat.h"$' "$work/copy/blur.glsl" || fail "could not put the header's loop into blur.glsl"
out=$(timeout 120 "$penumbra" check blur --glsl-root "$work/copy" --gpu-timeout 20 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" -eq 1 ] || fail "header loop: expected exit 1 (a false PASS before), got $status"
printf '%s\n' "$out" | grep -q "^blur: FAIL passes/blur.comp: dispatch: the loop at pn_repeat.h:1 ran past" ||
  fail "header loop: no message naming the loop at pn_repeat.h:1"
echo "broken_copy_commands: ok"
