#!/bin/sh
# figures_match_docs.sh PENUMBRA IMAGES SCRATCH
# Issue 26 B19: `penumbra figures` draws, byte for byte, the pictures committed
# in docs/images (on llvmpipe, where they were drawn): a change to a module
# that changes a picture fails here until the picture is drawn again
# (`penumbra figures --out docs/images`). Exit 77 without a GL context, or on
# another renderer (its rounding may differ in the last bit).
set -u
penumbra=$1 images=$2 scratch=$3
fail() { printf 'figures_match_docs: %s\n' "$1"; exit 1; }
info=$("$penumbra" info 2>&1)
case $? in 0) ;; 3) echo "SKIPPED: no GL context"; exit 77 ;; *) printf '%s\n' "$info"; fail "info failed" ;; esac
printf '%s\n' "$info" | grep -q llvmpipe || { echo "SKIPPED: not llvmpipe"; exit 77; }
rm -rf "$scratch"
"$penumbra" figures --out "$scratch" >/dev/null || fail "figures failed"
count=0
for drawn in "$scratch"/*.png; do
  name=$(basename "$drawn")
  [ -f "$images/$name" ] || fail "$name is drawn but not in $images"
  cmp -s "$drawn" "$images/$name" || fail "$name differs from $images/$name: run \`penumbra figures --out docs/images\`"
  count=$((count + 1))
done
[ "$count" -gt 0 ] || fail "figures drew nothing"
echo "figures_match_docs: ok ($count pictures)"
