#!/bin/sh
# check_all_gl.sh PENUMBRA OUT
# Every registered check on the library's modules, every case listed (`check -v`), on GL 4.5 (EGL
# surfaceless): must pass. Its output goes to OUT for cli_check_{vulkan,hlsl}_vs_gl (a ctest
# fixture), which compares the Vulkan and HLSL runs' case names and verdicts with it — so the
# library's GL run is made once, not once a module (check_gl.sh runs the broken copies only).
# Exit 77 (skipped) when there is no GL context.
set -u
penumbra=$1 out=$2
rm -f "$out"
"$penumbra" check -v --backend egl-surfaceless >"$out.part" 2>"$out.err"
status=$?
case $status in
  0) mv "$out.part" "$out" && tail -n 30 "$out" | grep -v ': pass ' ; exit 0 ;;
  3) echo "SKIPPED: $(cat "$out.err")"; rm -f "$out.part"; exit 77 ;;
  *) cat "$out.part" "$out.err"; rm -f "$out.part"; echo "check on the library's modules: exit $status, expected 0"; exit 1 ;;
esac
