#!/bin/sh
# unreadable_directory.sh PENUMBRA
# lint of a directory holding a subdirectory it may not read fails with one
# line naming that subdirectory and exit 2 (it used to abort on an uncaught
# std::filesystem::filesystem_error). Root reads everything, so as root the
# command runs as user nobody (setpriv) on a copy of the binary in a fresh
# temporary directory (the build tree may sit where nobody cannot reach);
# exit 77 (skipped) where that cannot be done.
set -u
penumbra=$1
work=$(mktemp -d) || { echo "unreadable_directory: cannot make a temporary directory"; exit 1; }
trap 'chmod -R u+rwx "$work" 2>/dev/null; rm -rf "$work"' EXIT
fail() { printf 'unreadable_directory: %s\n' "$1"; exit 1; }
mkdir -p "$work/tree/locked" && cp "$penumbra" "$work/penumbra" || fail "cannot fill $work"
penumbra=$work/penumbra
printf 'float pnHalf(float x) { return 0.5 * x; }\n' > "$work/tree/a.glsl"
printf 'float pnTwice(float x) { return 2.0 * x; }\n' > "$work/tree/locked/b.glsl"
chmod 755 "$work" "$work/tree" && chmod 000 "$work/tree/locked"
as_user=""
if [ "$(id -u)" -eq 0 ]; then
  command -v setpriv >/dev/null 2>&1 || { echo "unreadable_directory: skipped: root without setpriv"; exit 77; }
  as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
  $as_user test -x "$penumbra" || { echo "unreadable_directory: skipped: nobody cannot run $penumbra"; exit 77; }
fi
out=$($as_user "$penumbra" lint "$work/tree" 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "expected exit 2, got $status: $out"
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "expected one line, got: $out"
printf '%s\n' "$out" | grep -q "penumbra: error: directory '$work/tree/locked': cannot be read (Permission denied)" ||
  fail "said: $out"
echo "unreadable_directory: ok"
