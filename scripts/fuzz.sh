#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang-14, ASan + UBSan, in build-fuzz/) and runs
# each for a bounded time: until RUNS executions or SECONDS seconds, whichever comes first, with
# -rss_limit_mb=2048 -timeout=2 per input. Seeds: tests/fuzz/corpus/<t>/ and
# tests/fuzz/regressions/<t>/ (read only); inputs found while fuzzing go to
# build-fuzz/fuzz-corpus/<t>/, crashes to build-fuzz/fuzz-artifacts/<t>/. Prints one summary
# line per target (also in build-fuzz/fuzz-summary.txt); exits 1 if any target found something.
#
# Usage: scripts/fuzz.sh [TARGET...]          (default: every target)
# Env:   INDOORMAP_FUZZ_RUNS     (default 1000000)   executions per target
#        INDOORMAP_FUZZ_SECONDS  (default 120)       seconds per target
#        INDOORMAP_JOBS          (default 2)         build parallelism
# Nightly length: INDOORMAP_FUZZ_RUNS=10000000 INDOORMAP_FUZZ_SECONDS=600 scripts/fuzz.sh
# A finding: reproduce with build-fuzz/bin/fuzz_<t> <crash file>, minimise with
# -minimize_crash=1 -runs=10000, fix, and add the file to tests/fuzz/regressions/<t>/ (ctest
# replays it through test_fuzz_replay in every build).
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${INDOORMAP_FUZZ_RUNS:-1000000}"
seconds="${INDOORMAP_FUZZ_SECONDS:-120}"
scripts/setup.sh build-fuzz -DINDOORMAP_FUZZ=ON -DINDOORMAP_BUILD_TESTS=OFF -DINDOORMAP_BUILD_BENCH=OFF

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for d in tests/fuzz/corpus/*/; do targets+=("$(basename "$d")"); done
fi
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
summary=build-fuzz/fuzz-summary.txt
: >"$summary"
failed=0
for t in "${targets[@]}"; do
  bin=build-fuzz/bin/fuzz_$t
  [ -x "$bin" ] || { echo "fuzz: no binary $bin (is '$t' in tests/fuzz/CMakeLists.txt?)" >&2; exit 1; }
  work=build-fuzz/fuzz-corpus/$t art=build-fuzz/fuzz-artifacts/$t log=build-fuzz/fuzz-$t.log
  mkdir -p "$work" "$art" tests/fuzz/regressions/"$t"
  start=$(date +%s)
  rc=0
  # A fixed seed makes the CI run reproducible: the same inputs in the same order, so a clean run
  # here predicts a clean run there (a slower machine only stops earlier in the same sequence).
  "$bin" -seed=1 -rss_limit_mb=2048 -timeout=2 -runs="$runs" -max_total_time="$seconds" \
    -print_final_stats=1 -artifact_prefix="$art/" "$work" tests/fuzz/corpus/"$t" \
    tests/fuzz/regressions/"$t" >"$log" 2>&1 || rc=$?
  secs=$(($(date +%s) - start))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  result=clean
  if [ $rc -ne 0 ]; then
    result="FAILED (exit $rc): $(ls "$art" | tr '\n' ' ')"
    failed=1
    grep -E "ERROR|SUMMARY|indoormap fuzz target|runtime error" "$log" | head -5 >&2 || true
  fi
  line=$(printf '%-8s %10s execs %5ss %8s exec/s  cov %-6s corpus %-5s peak %4s MB  %s' "$t" \
    "${execs:-?}" "$secs" "$(( ${execs:-0} / (secs > 0 ? secs : 1) ))" "${cov:-?}" \
    "$(ls "$work" | wc -l)" "${rss:-?}" "$result")
  echo "fuzz: $line" >&2
  echo "$line" >>"$summary"
done
exit $failed
