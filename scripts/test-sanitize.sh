#!/bin/sh
# .ci/run's second step: build penumbra and its unit tests with AddressSanitizer and UBSan
# into build-asan/ (or $PENUMBRA_SANITIZE_BUILD_DIR), and run the unit and CLI tests under
# them; any ASan, UBSan or LeakSanitizer report fails the run. Arguments go to ctest.
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

# Each report also goes to a file, and a process with one exits 23: a report from a command
# whose failure a test expects (exit 1 or 2, or any nonzero) still fails the run.
reports=$build/sanitizer-reports
rm -rf "$reports" && mkdir -p "$reports"
export LD_PRELOAD="$build/keep_loaded.so"
# verify_asan_link_order=0: keep_loaded.so comes before libasan; it defines only dlclose.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:exitcode=23:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:verify_asan_link_order=0:log_path=$reports/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=23:log_path=$reports/ubsan"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"

# The module checks on a GL context that take minutes under ASan (the instrumented CPU
# references) are left out; blur, pcf, poisson_pcss and minmax_mip stay, on both backends,
# with every other CLI test, GL or not.
slow='^cli_check_(depth_pyramid|traversal|pcss_regions|pipeline|summed_area)_|^cli_check_es310$|^cli_broken_copy_commands$'
cd "$build"
status=0
ctest --output-on-failure --no-tests=error -R '^unit$' "$@" || status=1
ctest --output-on-failure --no-tests=error -j "$(nproc)" -L cli -E "$slow" "$@" || status=1
for report in "$reports"/*; do
  [ -e "$report" ] || break
  printf '== %s\n' "$report" && cat "$report"
  status=1
done
[ "$status" -eq 0 ] || echo "penumbra: the sanitizer run failed (test failures or reports above)" >&2
exit "$status"
