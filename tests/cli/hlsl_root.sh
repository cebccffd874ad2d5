#!/bin/sh
# hlsl_root.sh PENUMBRA GLSL_DIR WORK_DIR
# Issue 39 (4): `check --api hlsl --hlsl-root DIR` never falls back to the library's export in
# silence:
# - a root that supplies no copy — empty, only a dangling link, a link loop, a directory named
#   pcf.hlsl, a wrongly cased PCF.hlsl, only files named for no entry — is refused before any
#   work: one line naming the root and what was expected, exit 2 (each used to pass);
# - with a root holding passes/region_query.comp's export and blur.hlsl: region says it ran the
#   copy, sample_table that it ran the library's exports (none of its passes has a copy), and
#   blur.hlsl is named as read by no check run.
# Exit 77 (skipped) without a Vulkan device (the refusals come before the device).
set -u
penumbra=$1 glsl=$2 work=$3
fail() { printf 'hlsl_root: %s\n' "$1"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"
mkdir empty dangling loop directory/ directory/pcf.hlsl cased others good || fail "cannot make the roots"
ln -s missing.hlsl dangling/pcf.hlsl && ln -s exact_pcss.hlsl loop/exact_pcss.hlsl || fail "cannot make links"
"$penumbra" bundle pcf.glsl --glsl-root "$glsl" --target hlsl -o cased/PCF.hlsl || fail "bundle pcf.glsl"
echo '// notes' > others/notes.hlsl
"$penumbra" bundle passes/region_query.comp --glsl-root "$glsl" --target hlsl -o good/region_query.hlsl ||
  fail "bundle passes/region_query.comp"
"$penumbra" bundle passes/blur.comp --glsl-root "$glsl" --target hlsl -o good/blur.hlsl || fail "bundle passes/blur.comp"

refused() {
  root=$1 regex=$2
  out=$("$penumbra" check exports --api hlsl --glsl-root "$glsl" --hlsl-root "$root" 2>&1)
  status=$?
  printf '%s\n' "$out"
  [ "$status" -eq 2 ] || fail "--hlsl-root $root: expected exit 2, got $status"
  [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "--hlsl-root $root: expected one line"
  printf '%s\n' "$out" | grep -Eq -- "^penumbra: error: --hlsl-root $root: $regex" ||
    fail "--hlsl-root $root: not 'penumbra: error: --hlsl-root $root: $regex'"
}
refused empty 'no HLSL copy there \(no \.hlsl file directly in it\): expected X\.hlsl.* for an export entry X \(.*exact_pcss, .*pcf, poisson_pcss, savsm, vogel_pcss, vsm'
refused dangling 'pcf\.hlsl is a link to nothing \(missing\.hlsl\): expected a regular file'
refused loop 'exact_pcss\.hlsl is a link that cannot be followed'
refused directory 'pcf\.hlsl is a directory: expected a regular file'
refused cased 'PCF\.hlsl names the entry pcf in another case \(names are case-sensitive\): expected pcf\.hlsl'
refused others 'no HLSL copy there \(its \.hlsl files name no entry: notes\.hlsl\)'

out=$("$penumbra" check region sample_table --api hlsl --glsl-root "$glsl" --hlsl-root good 2>&1)
status=$?
[ "$status" -eq 3 ] && { echo "SKIPPED: no Vulkan device"; exit 77; }
printf '%s\n' "$out"
[ "$status" -eq 0 ] || fail "region sample_table on the good root: expected exit 0, got $status"
printf '%s\n' "$out" | grep -q '^region: --hlsl-root: ran good/region_query\.hlsl$' ||
  fail "region does not say it ran good/region_query.hlsl"
printf '%s\n' "$out" | grep -Eq '^sample_table: --hlsl-root: no copy ran; the library.s export ran for passes/sample_table_query.* \(no copy of it in good\)' ||
  fail "sample_table does not say it ran the library's exports"
printf '%s\n' "$out" | grep -q '^--hlsl-root good: not read by the checks run: blur\.hlsl ' ||
  fail "blur.hlsl is not named as unread"
echo "hlsl_root: ok"
