#!/bin/sh
# Two clones of one commit bundle the same bytes (issue 41): a bundle's header names the glsl root by
# its path inside the repository and the last commit that changed it, never by where the clone lies.
# Usage: bundle_reproducible.sh PENUMBRA REPOSITORY WORK
penumbra=$1 repository=$2 work=$3
git -C "$repository" rev-parse --git-dir >/dev/null 2>&1 || { echo "$repository is not a git checkout: skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work" || exit 1
git clone --quiet "$repository" "$work/first" && git clone --quiet "$repository" "$work/second-clone" || {
  echo "cannot clone $repository"; exit 1; }
for form in "pcf.glsl --target hlsl" "fast_pcss.glsl --target msl" "blur.glsl --target gl450"; do
  set -- $form
  "$penumbra" bundle "$work/first/glsl/$1" $2 $3 -o "$work/first.out" || exit 1
  "$penumbra" bundle "$work/second-clone/glsl/$1" $2 $3 -o "$work/second.out" || exit 1
  cmp -s "$work/first.out" "$work/second.out" || {
    echo "bundle $form differs between two clones:"; diff "$work/first.out" "$work/second.out" | head -10; exit 1; }
  if grep -q "$work" "$work/first.out"; then echo "bundle $form names the clone's path"; exit 1; fi
  echo "bundle $form: the same $(wc -c < "$work/first.out") bytes from both clones"
done
"$penumbra" bundle "$work/first/glsl/pcf.glsl" --target hlsl | grep -q "^// from: glsl/ of its repository at commit [0-9a-f]\{40\}, the last commit that changed it$" || {
  echo "the HLSL export's header does not name glsl/ and its commit"; exit 1; }
echo "the header names glsl/ of the repository and its last commit"
