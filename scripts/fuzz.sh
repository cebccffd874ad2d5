#!/bin/sh
# scripts/fuzz.sh [SECONDS]: the libFuzzer targets of fuzz/ (docs/reliability.md, "Fuzzing").
# Installs what is missing, configures and builds build-fuzz/ with clang, then per target:
# replays its regression inputs (fixtures/fuzz/regressions/<target>/), and fuzzes for
# SECONDS (default 60) a copy of its seed corpus (fixtures/fuzz/<target>/, never written
# to) with its dictionary (fixtures/fuzz/<target>.dict).
# Exit 1 when any target crashed, leaked, ran out of memory or timed out: the target and
# the artifact (the input, kept under build-fuzz/fuzz-artifacts/<target>/) are named.
# A crash inside Assimp in the model loader's import child (runner/scene/model.cpp) is
# contained by design — the loader refuses the file — and is listed, not failed.
# Environment: PENUMBRA_FUZZ_BUILD_DIR (default build-fuzz), PENUMBRA_FUZZ_TARGETS
# (default: flatten diagnostic techniques model cli).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
case "$seconds" in
  '' | *[!0-9]* | 0) echo "fuzz.sh: error: seconds '$seconds': expected a whole number > 0" >&2; exit 2 ;;
esac
build=${PENUMBRA_FUZZ_BUILD_DIR:-$root/build-fuzz}
targets=${PENUMBRA_FUZZ_TARGETS:-flatten diagnostic techniques model cli}

"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DPENUMBRA_FUZZ=ON -DPENUMBRA_TESTS=OFF -DPENUMBRA_SANITIZE=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target penumbra_fuzz

work=$(mktemp -d "${TMPDIR:-/tmp}/penumbra-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
mkdir -p "$build/fuzz-logs"

# Runs a target binary with the sanitizers' options, in the target's work directory.
run_target() {  # TARGET ARGS...
  t=$1
  shift
  (cd "$work/$t" && TMPDIR="$work/$t/tmp" \
     ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1" \
     UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
     "$build/fuzz/fuzz_$t" "$@")
}

# Whether a log's stack traces all start in Assimp: for each trace, the first frame in
# libassimp or in penumbra's own sources decides (frames in the C/C++ runtime and the
# sanitizers' interceptors are passed over). No trace at all, or one of ours: no.
traces_start_in_assimp() {  # LOG
  awk -v ours1="$root/runner/" -v ours2="$root/fuzz/" '
    function close_trace() { if (open) { if (decided == "assimp") assimp++; else other++ } open = 0 }
    /^ *#[0-9]+ 0x/ {
      if ($1 == "#0") { close_trace(); open = 1; decided = "" }
      if (open && decided == "") {
        if (index($0, "libassimp")) decided = "assimp"
        else if (index($0, ours1) || index($0, ours2)) decided = "ours"
      }
    }
    END { close_trace(); exit !(assimp > 0 && other == 0) }' "$1"
}

failed=""
for t in $targets; do
  binary="$build/fuzz/fuzz_$t"
  seeds="$root/fixtures/fuzz/$t"
  if [ ! -x "$binary" ] || [ ! -d "$seeds" ]; then echo "fuzz.sh: error: unknown target '$t'" >&2; exit 2; fi
  artifacts="$build/fuzz-artifacts/$t"
  log="$build/fuzz-logs/$t.log"
  rm -rf "$artifacts" && mkdir -p "$artifacts" "$work/$t/tmp" "$work/$t/replay"
  bad=""

  # Every crash found so far stays fixed (or contained).
  regressions="$root/fixtures/fuzz/regressions/$t"
  if [ -d "$regressions" ]; then
    replay_log="$build/fuzz-logs/$t.regressions.log"
    replay_status=0
    run_target "$t" -artifact_prefix="$work/$t/replay/" "$regressions"/* >"$replay_log" 2>&1 || replay_status=$?
    if [ "$replay_status" -ne 0 ]; then
      bad="a regression input, exit $replay_status: $replay_log"
      echo "fuzz.sh: FAILED: fuzz_$t on its regression inputs (exit $replay_status); log: $replay_log" >&2
    else
      echo "fuzz.sh: fuzz_$t: $(find "$regressions" -type f | wc -l) regression inputs replayed clean"
    fi
  fi

  cp -R "$seeds" "$work/$t/corpus"
  dict=""
  [ -f "$root/fixtures/fuzz/$t.dict" ] && dict="-dict=$root/fixtures/fuzz/$t.dict"
  echo "fuzz.sh: fuzz_$t for $seconds s ($(find "$seeds" -type f | wc -l) seeds)"
  start=$(date +%s)
  status=0
  # shellcheck disable=SC2086
  run_target "$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -detect_leaks=1 \
    -artifact_prefix="$artifacts/" -print_final_stats=1 $dict corpus >"$log" 2>&1 || status=$?
  elapsed=$(( $(date +%s) - start ))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -n 1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 |
         sed -E 's/^#[0-9]+[[:space:]]+[A-Z]+[[:space:]]+//; s/[[:space:]]+(lim|exec\/s|rss|L|MS):.*//')
  echo "fuzz.sh: fuzz_$t: ${elapsed} s, ${runs:-?} runs (${rate:-?}/s), ${last:-no coverage line}, peak rss ${rss:-?} MB"

  found=$(find "$artifacts" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | sort)
  if [ "$status" -ne 0 ]; then
    bad="${bad:+$bad; }exit $status"
  else
    # The fuzzer itself survived: a crash artifact came from a child process (the import child).
    kept=""
    for a in $found; do
      replay="$a.replay.log"
      if run_target "$t" -artifact_prefix="$work/$t/replay/" "$a" >"$replay" 2>&1 && traces_start_in_assimp "$replay"; then
        mkdir -p "$artifacts/contained"
        mv "$a" "$replay" "$artifacts/contained/"
      else
        kept="$kept $a"
      fi
    done
    found=${kept# }
    [ -z "$found" ] || bad="${bad:+$bad; }a crash in a child process, not in Assimp"
    contained=$(find "$artifacts/contained" -type f ! -name '*.replay.log' 2>/dev/null | wc -l)
    [ "$contained" -eq 0 ] ||
      echo "fuzz.sh: fuzz_$t: $contained inputs crashed Assimp in the import child, refused as bad input: $artifacts/contained/"
  fi
  if [ -n "$bad" ]; then
    failed="$failed $t"
    echo "fuzz.sh: FAILED: fuzz_$t ($bad); log: $log" >&2
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error:|ALARM|.*out-of-memory|.*deadly signal)' "$log" | head -n 5 >&2 || true
    for a in $found; do echo "fuzz.sh:   artifact: $a (replay: $binary $a)" >&2; done
  fi
done

if [ -n "$failed" ]; then
  echo "fuzz.sh: failed:$failed" >&2
  exit 1
fi
echo "fuzz.sh: every target ran $seconds s clean:$targets"
