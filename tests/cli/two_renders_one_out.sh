#!/bin/sh
# two_renders_one_out.sh PENUMBRA SCRATCH
# Issue 26 B7: two `render` processes into one --out each write through a
# temporary of their own: both exit 0, the sheet is there, no temporary is
# left (they used to share NAME.partial: one failed, the other lost its sheet).
# Exit 77 (skipped) without a context.
set -u
penumbra=$1 scratch=$2
fail() { printf 'two_renders_one_out: %s\n' "$1"; exit 1; }
"$penumbra" info >/dev/null 2>&1
case $? in 0) ;; 3) echo "SKIPPED: no GL context"; exit 77 ;; *) fail "info failed" ;; esac
rm -rf "$scratch" && mkdir -p "$scratch" || fail "cannot make $scratch"
args="render --map-size 64 --screen 64 --techniques pcf,poisson --out $scratch/out"
# shellcheck disable=SC2086  # the words of the command
"$penumbra" $args >"$scratch/a.log" 2>&1 &
a=$!
# shellcheck disable=SC2086
"$penumbra" $args >"$scratch/b.log" 2>&1 &
b=$!
wait $a; sa=$?
wait $b; sb=$?
cat "$scratch/a.log" "$scratch/b.log"
[ "$sa" -eq 0 ] && [ "$sb" -eq 0 ] || fail "expected both to exit 0, got $sa and $sb"
[ -s "$scratch/out/boxes_sheet.png" ] || fail "the sheet is missing"
ls -a "$scratch/out" | grep -q '^\.pn-' && fail "a temporary was left: $(ls -a "$scratch/out" | grep '^\.pn-')"
rm -rf "$scratch"
echo "two_renders_one_out: ok"
