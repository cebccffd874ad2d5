#!/bin/sh
# render_interrupted.sh PENUMBRA SCRATCH
# Issue 26 B8: SIGINT or SIGTERM at any moment of `render` leaves no temporary
# (`.pn-*.tmp`), and a set of files is whole exactly when its manifest is there:
# every file the manifest lists exists, with the bytes its line's hash names
# (issue 39 C10: `FNV-1a-64  NAME`, so the manifest vouches only for the
# bytes this run wrote, never for another run's). Runs the same render interrupted at
# several delays (before, during and after its writes), then once to the end.
# Exit 77 (skipped) without a GL context.
set -u
penumbra=$1 scratch=$2
fail() { printf 'render_interrupted: %s\n' "$1"; exit 1; }
"$penumbra" info >/dev/null 2>&1
case $? in 0) ;; 3) echo "SKIPPED: no GL context"; exit 77 ;; *) fail "info failed" ;; esac
rm -rf "$scratch" && mkdir -p "$scratch" || fail "cannot make $scratch"
out=$scratch/out
# `exec`: the signal below must reach penumbra itself. Without it `run &` is a subshell that
# waits on penumbra: SIGTERM killed that shell and left the render running on (into the next
# round's writes), and SIGINT, which sh ignores in background commands, reached no one.
run() {
  exec "$penumbra" render --map-size 128 --screen 128 --truth-samples 4 --repeats 1 --techniques pcf,fast --out "$out" \
    >"$scratch/log" 2>&1
}
# FNV-1a 64 of a file, 16 hex digits, as the manifest writes it.
fnv() {
  python3 -c 'import sys
h = 0xcbf29ce484222325
for c in open(sys.argv[1], "rb").read(): h = ((h ^ c) * 0x100000001b3) % (1 << 64)
print("%016x" % h)' "$1"
}
check_out() {
  left=$(find "$out" -name '.pn-*.tmp' 2>/dev/null)
  [ -z "$left" ] || fail "$1: left $left"
  if [ -e "$out/boxes_manifest.txt" ]; then
    problem=$(python3 -c 'import os, sys
out = sys.argv[1]
for line in open(os.path.join(out, "boxes_manifest.txt")):
    digest, name = line.rstrip("\n").split("  ", 1)
    path = os.path.join(out, name)
    if not os.path.isfile(path):
        print("the manifest lists " + name + ", which is not there"); break
    h = 0xcbf29ce484222325
    for c in open(path, "rb").read(): h = ((h ^ c) * 0x100000001b3) % (1 << 64)
    if "%016x" % h != digest:
        print(name + " does not hold the bytes its manifest line hashes"); break' "$out")
    [ -z "$problem" ] || fail "$1: $problem"
  fi
}
# The delays are fractions of one whole render timed here, so that the signals land before,
# during and after the writes on a fast build and under the sanitizers alike.
start=$(date +%s.%N)
(run) || { cat "$scratch/log"; fail "the timed whole render failed"; }
whole=$(python3 -c 'import sys, time; print(time.time() - float(sys.argv[1]))' "$start")
rm -rf "$out"
interrupted=0
for signal in INT TERM; do
  for fraction in 0.15 0.35 0.5 0.6 0.75; do
    delay=$(python3 -c 'import sys; print("%.3f" % (float(sys.argv[1]) * float(sys.argv[2])))' "$whole" "$fraction")
    (run) &
    pid=$!
    sleep "$delay"
    kill -s "$signal" "$pid" 2>/dev/null
    wait "$pid"
    status=$?
    case $status in
      0) ;;  # done before the signal
      130|143) interrupted=$((interrupted + 1)) ;;  # ended by SIGINT / SIGTERM
      *) cat "$scratch/log"; fail "SIG$signal after $delay s: exit $status" ;;
    esac
    check_out "SIG$signal after $delay s"
  done
done
# A test that never interrupted anything proves nothing.
[ "$interrupted" -ge 3 ] || fail "only $interrupted of 10 renders were interrupted (a whole render took $whole s)"
(run) || { cat "$scratch/log"; fail "the whole render failed"; }
check_out "the whole render"
[ -e "$out/boxes_manifest.txt" ] || fail "a whole render wrote no manifest"
[ "$(wc -l <"$out/boxes_manifest.txt")" -eq 9 ] || fail "the manifest lists $(wc -l <"$out/boxes_manifest.txt") files, expected 9"
# Another run's bytes under a listed name are disowned: its hash no longer matches.
printf 'another run\n' >"$out/boxes_pcf_lit.png"
name=boxes_pcf_lit.png
hash=$(sed -n "s/^\([0-9a-f]*\)  $name\$/\1/p" "$out/boxes_manifest.txt")
[ -n "$hash" ] || fail "the manifest has no line for $name"
[ "$(fnv "$out/$name")" != "$hash" ] || fail "the manifest's hash of $name matches another run's bytes"
echo "render_interrupted: ok"
