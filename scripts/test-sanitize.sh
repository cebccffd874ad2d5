#!/bin/sh
# .ci/run's second step: build penumbra and its unit tests with AddressSanitizer and UBSan
# into build-asan/ (or $PENUMBRA_SANITIZE_BUILD_DIR), and run the unit and CLI tests under
# them; any ASan, UBSan or LeakSanitizer report fails the run. Arguments go to both ctest
# runs (the unit test, then the CLI tests).
# What runs and why: docs/reliability.md, "Sanitizers (ASan + UBSan)".
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PENUMBRA_SANITIZE_BUILD_DIR:-$root/build-asan}
"$root/scripts/install-deps.sh"
# -O1 -g1: ASan's recommended level, and line tables only: half the compile time of -O2 -g.
PENUMBRA_BUILD_DIR=$build PENUMBRA_BUILD_TARGETS="penumbra penumbra_unit_tests" \
  "$root/scripts/build.sh" -DPENUMBRA_SANITIZE=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
# Keeps Mesa's DRI driver mapped after eglTerminate, so that a leak report can name it.
cc -shared -fPIC -O1 -o "$build/keep_loaded.so" "$root/tests/sanitize/keep_loaded.c"

# A process with a report exits 23, which no test expects. So that a report from a command
# whose failure a test expects (any nonzero, its stderr discarded) still fails the run, ASan
# and LSan also write each report to a file, and UBSan's lines (GCC's runtime writes them to
# stderr whatever log_path says) are looked for in what ctest kept of every test's output.
reports=$build/sanitizer-reports
rm -rf "$reports" && mkdir -p "$reports"
export LD_PRELOAD="$build/keep_loaded.so"
# verify_asan_link_order=0: keep_loaded.so comes before libasan; it defines only dlclose.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:exitcode=23:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:verify_asan_link_order=0:log_path=$reports/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=23"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"

# The module checks on a GL context that take a minute or more each under ASan (their CPU
# references, instrumented) are left out: ~4 minutes on 2 cores; so are the runs of every check on
# the library (cli_check_all_gl on GL, check_vulkan.py on vulkan and hlsl: over 8 minutes): the
# broken copies run the same checks on every executor. PENUMBRA_SANITIZE_ALL=1 runs them too. Every other CLI
# test runs, GL or not.
slow='^cli_check_(depth_pyramid|traversal|pcss_regions)_|^cli_check_es310$|^cli_check_all_gl$|^cli_check_(vulkan|hlsl)_vs_gl$'
[ "${PENUMBRA_SANITIZE_ALL:-0}" = 1 ] && slow='^$'  # no test has an empty name
cd "$build"
status=0
run_ctest() {
  ctest --output-on-failure --no-tests=error "$@" || status=1
  if grep -E ':[0-9]+:[0-9]+: runtime error: ' Testing/Temporary/LastTest.log; then status=1; fi
}
run_ctest -R '^unit$' "$@"
run_ctest -j "$(nproc)" -L cli -E "$slow" "$@"
# Assimp's importers crash on some malformed files (docs/reliability.md, "Fuzzing"), by design
# inside the child process that runs them (runner/scene/model.cpp, read_triangles_in_child),
# and the tests check the parent's answer. Such a report is passed over when it comes from
# that child and its stack starts in libassimp (the sanitizers' and C library's frames skipped).
in_assimp() {
  grep -q ' in read_triangles_in_child ' "$1" &&
    awk '/^ *#[0-9]+ / && !/libsanitizer|libasan|\/libc\.so|interceptor/ { exit($0 ~ /libassimp\.so/ ? 0 : 1) }' "$1"
}
for report in "$reports"/*; do
  [ -e "$report" ] || break
  if in_assimp "$report"; then
    echo "penumbra: $report: Assimp crashed in the model-reading child, as expected on a malformed file"
    continue
  fi
  printf '== %s\n' "$report" && cat "$report"
  status=1
done
[ "$status" -eq 0 ] || echo "penumbra: the sanitizer run failed (test failures or reports above)" >&2
exit "$status"
