#!/bin/sh
# render_interrupted.sh PENUMBRA SCRATCH
# Issue 26 B8: SIGINT or SIGTERM at any moment of `render` leaves no temporary
# (`.pn-*.tmp`), and a set of files is whole exactly when its manifest is there:
# every file the manifest lists exists. Runs the same render interrupted at
# several delays (before, during and after its writes), then once to the end.
# Exit 77 (skipped) without a GL context.
set -u
penumbra=$1 scratch=$2
fail() { printf 'render_interrupted: %s\n' "$1"; exit 1; }
"$penumbra" info >/dev/null 2>&1
case $? in 0) ;; 3) echo "SKIPPED: no GL context"; exit 77 ;; *) fail "info failed" ;; esac
rm -rf "$scratch" && mkdir -p "$scratch" || fail "cannot make $scratch"
out=$scratch/out
run() {
  "$penumbra" render --map-size 128 --screen 128 --truth-samples 4 --repeats 1 --methods pcf,fast --out "$out" \
    >"$scratch/log" 2>&1
}
check_out() {
  left=$(find "$out" -name '.pn-*.tmp' 2>/dev/null)
  [ -z "$left" ] || fail "$1: left $left"
  if [ -e "$out/boxes_manifest.txt" ]; then
    while read -r name; do
      [ -f "$out/$name" ] || fail "$1: the manifest lists $name, which is not there"
    done <"$out/boxes_manifest.txt"
  fi
}
for signal in INT TERM; do
  for delay in 0.2 0.6 1.0 1.4 1.8; do
    run &
    pid=$!
    sleep "$delay"
    kill -s "$signal" "$pid" 2>/dev/null
    wait "$pid"
    status=$?
    case $status in
      0|130|143) ;;  # done before the signal, or ended by SIGINT / SIGTERM
      *) cat "$scratch/log"; fail "SIG$signal after $delay s: exit $status" ;;
    esac
    check_out "SIG$signal after $delay s"
  done
done
run || { cat "$scratch/log"; fail "the whole render failed"; }
check_out "the whole render"
[ -e "$out/boxes_manifest.txt" ] || fail "a whole render wrote no manifest"
[ "$(wc -l <"$out/boxes_manifest.txt")" -eq 9 ] || fail "the manifest lists $(wc -l <"$out/boxes_manifest.txt") files, expected 9"
echo "render_interrupted: ok"
