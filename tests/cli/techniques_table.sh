#!/bin/sh
# techniques_table.sh PENUMBRA CLI_MD
# docs/cli.md's table of techniques is `penumbra techniques --markdown` word for word (issue 41:
# a technique added to the registry appears in cli.md, or this fails and says how to write it).
set -u
penumbra=$1 page=$2
fail() { printf 'techniques_table: %s\n' "$1"; exit 1; }
want=$("$penumbra" techniques --markdown) || fail "penumbra techniques --markdown failed"
have=$(sed -n '/^<!-- techniques: penumbra techniques --markdown -->$/,/^<!-- \/techniques -->$/p' "$page" | sed '1d;$d')
[ -n "$have" ] || fail "$page has no table between <!-- techniques: penumbra techniques --markdown --> and <!-- /techniques -->"
if [ "$want" != "$have" ]; then
  printf '%s\n' "$want" > "${TMPDIR:-/tmp}/techniques_table.want.$$"
  printf '%s\n' "$have" | diff "${TMPDIR:-/tmp}/techniques_table.want.$$" - | head -20
  rm -f "${TMPDIR:-/tmp}/techniques_table.want.$$"
  fail "$page's table differs from the registry (< registry, > page): paste \`penumbra techniques --markdown\` between the markers"
fi
echo "techniques_table: ok ($(printf '%s\n' "$want" | tail -n +3 | wc -l) techniques)"
