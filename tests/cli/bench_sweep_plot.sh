#!/bin/sh
# bench_sweep_plot.sh PENUMBRA PLOT_SCRIPT WORKDIR
# A tiny `penumbra bench sweep` (through gl_or_skip.sh: exit 77 without a GL
# context) writes its JSON; scripts/plot_sweep.py (Debian's python3 and
# python3-matplotlib) turns it into a PNG, which must exist and start with the
# PNG signature.
penumbra=$1 plot=$2 work=$3
here=$(dirname "$0")
rm -rf "$work" && mkdir -p "$work" || exit 1
sh "$here/gl_or_skip.sh" "$penumbra" "time growth from the first to the last factor: +poisson [0-9.]+x \(x1 -> x2\) +fast " \
  bench sweep --sizes 32 --widths 1,2 --scenes tall_blocker --techniques poisson,fast --repeats 1 --truth-samples 2 \
  --json "$work/sweep.json"
status=$?
[ "$status" -eq 0 ] || exit "$status"
/usr/bin/python3 "$plot" "$work/sweep.json" "$work/sweep.png" || { echo "plot_sweep.py failed"; exit 1; }
[ -s "$work/sweep.png" ] || { echo "no $work/sweep.png"; exit 1; }
signature=$(head -c 8 "$work/sweep.png" | od -An -tx1 | tr -d ' \n')
[ "$signature" = "89504e470d0a1a0a" ] || { echo "$work/sweep.png does not start with the PNG signature ($signature)"; exit 1; }
echo "sweep.png: PNG, $(wc -c < "$work/sweep.png") bytes"
