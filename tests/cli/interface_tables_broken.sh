#!/bin/sh
# interface_tables_broken.sh ROOT PENUMBRA WORKDIR
# interface_tables.py (issue 53) fails on a copy of the pages where the chain build's texel list
# moved register, naming the page and the line, and where a required pass's table is gone.
set -u
root=$1 penumbra=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
cp -r "$root/glsl" "$root/docs" "$work/" || exit 1
sed -i 's/^| 4 | t4 | `PnTexelList`/| 4 | t5 | `PnTexelList`/' "$work/docs/modules/minmax_mip.md"
sed -i '/<!-- interface passes\/vsm_moments.comp -->/,/<!-- \/interface -->/d' "$work/docs/modules/vsm.md"
out=$(python3 "$root/tests/interface_tables.py" "$work" "$penumbra") && { echo "the broken copy passed"; exit 1; }
echo "$out"
echo "$out" | grep -q "docs/modules/minmax_mip.md: passes/minmax_mip_build.comp's table differs from its code at table line 7" ||
  { echo "the moved register is not named"; exit 1; }
echo "$out" | grep -q "passes/vsm_moments.comp: no .* table on any page" || { echo "the missing table is not named"; exit 1; }
