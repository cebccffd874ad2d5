#!/bin/sh
# output_targets.sh PENUMBRA GLSL_DIR WORK_DIR
# Output files that are not plain files survive: a device is written in place
# (/dev/null accepts it, /dev/full fails with one line and exit 2), a symbolic
# link stays a link and its target gets the output; --json into a missing
# directory is refused before the bench runs (exit 2, seconds not minutes);
# a command whose standard output is full fails (exit 2, one line); a FIFO
# given as a module is refused, not read until it closes.
set -u
penumbra=$1 glsl=$2 work=$3
fail() { printf 'output_targets: %s\n' "$1"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"

"$penumbra" bundle "$glsl/blur.glsl" -o /dev/null || fail "bundle -o /dev/null: exit $?"
[ -c /dev/null ] || fail "/dev/null is no longer a character device"

out=$("$penumbra" bundle "$glsl/blur.glsl" -o /dev/full 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "bundle -o /dev/full: expected exit 2, got $status: $out"
printf '%s\n' "$out" | grep -q "output '/dev/full': write failed" || fail "bundle -o /dev/full said: $out"
[ -c /dev/full ] || fail "/dev/full is no longer a character device"

printf 'old\n' > "$work/target" && ln -s "$work/target" "$work/link" || fail "cannot make the link"
"$penumbra" bundle "$glsl/blur.glsl" -o "$work/link" || fail "bundle -o link: exit $?"
[ -L "$work/link" ] || fail "the link was replaced by a file"
grep -q "penumbra bundle of blur.glsl" "$work/target" || fail "the link's target does not hold the bundle"

# Issue 39 C13: /dev/stdout is the descriptor the caller opened, written as opened: a pipe (it
# used to be "its link cannot be followed"), a file opened to append to (not truncated).
out=$("$penumbra" poisson --count 4 -o /dev/stdout) || fail "poisson -o /dev/stdout into a pipe: exit $?"
printf '%s\n' "$out" | grep -q "PN_POISSON_DISK" || fail "poisson -o /dev/stdout into a pipe wrote: $out"
printf 'kept\n' >"$work/appended"
"$penumbra" poisson --count 4 -o /dev/stdout >>"$work/appended" || fail "poisson -o /dev/stdout >> file: exit $?"
[ "$(head -n 1 "$work/appended")" = kept ] || fail "-o /dev/stdout truncated a file opened to append to"
grep -q "PN_POISSON_DISK" "$work/appended" || fail "-o /dev/stdout >> file did not append the samples"

out=$("$penumbra" bench pyramid --sizes 64 --repeats 1 --json "$work/no/such/dir/x.json" 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "bench --json into a missing directory: expected exit 2, got $status: $out"
printf '%s\n' "$out" | grep -q "does not exist" || fail "bench --json said: $out"
printf '%s\n' "$out" | grep -q "backend" && fail "bench --json into a missing directory ran the bench first: $out"
for command in "poisson --count 4" "bundle $glsl/blur.glsl" "lint $glsl/blur.glsl"; do
  out=$("$penumbra" $command 2>&1 >/dev/full)
  status=$?
  [ "$status" -eq 2 ] || fail "$command > /dev/full: expected exit 2, got $status: $out"
  printf '%s\n' "$out" | grep -q "standard output: write failed" || fail "$command > /dev/full said: $out"
done
# A FIFO as input never blocks: lint and bundle refuse it (exit 2, one line).
mkfifo "$work/fifo.glsl" || fail "cannot make a FIFO"
for command in lint bundle; do
  out=$(timeout 20 "$penumbra" $command "$work/fifo.glsl" 2>&1)
  status=$?
  [ "$status" -eq 2 ] || fail "$command of a FIFO: expected exit 2, got $status: $out"
  printf '%s\n' "$out" | grep -q "special file" || fail "$command of a FIFO said: $out"
done
echo "output_targets: ok"
