#!/usr/bin/env bash
# Builds and runs the whole test suite with ctest (installs missing packages first).
#
# Usage: ./test.sh [--sanitize] [--fuzz] [--no-bench]
#   (no flag)    build/ (gcc, Release, with the benchmarks) and ctest.
#   --no-bench   build/ without the benchmarks (CI; the same as INDOORMAP_BUILD_BENCH=OFF).
#   --sanitize   then build-san/: clang-14, AddressSanitizer + UndefinedBehaviorSanitizer, -O2,
#                the test suite and the fuzz binaries from ONE configure (-DINDOORMAP_FUZZ=ON),
#                and the whole suite under it but the sweeps of tests/sanitizers/skip_tests.txt;
#                any report fails it.
#   --fuzz       then every libFuzzer target of tests/fuzz from build-san/, all within one budget
#                (scripts/fuzz.sh: INDOORMAP_FUZZ_BUDGET, default 900 s, for all, two at a
#                time, 50,000 executions at least).
# The same through the environment: INDOORMAP_TEST_SANITIZE=1, INDOORMAP_TEST_FUZZ=1.
# .ci/run uses all three with a 300 s fuzz budget. Every stage prints its duration, and the last
# lines list them all (CI's times: docs/robustness.md, "CI stages and their times").
set -euo pipefail
cd "$(dirname "$0")"
sanitize="${INDOORMAP_TEST_SANITIZE:-0}"
fuzz="${INDOORMAP_TEST_FUZZ:-0}"
bench="${INDOORMAP_BUILD_BENCH:-ON}"
for a in "$@"; do
  case "$a" in
    --sanitize) sanitize=1 ;;
    --fuzz) fuzz=1 ;;
    --no-bench) bench=OFF ;;
    -h | --help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "test.sh: unknown option '$a' (see --help)" >&2; exit 2 ;;
  esac
done
jobs="${INDOORMAP_JOBS:-2}"

t0=$(date +%s)
times=()
# stage NAME COMMAND...: runs it, prints and records how long it took.
stage() {
  local name=$1 start rc=0
  shift
  echo "test.sh: [$(date +%T)] $name" >&2
  start=$(date +%s)
  "$@" || rc=$?
  local s=$(($(date +%s) - start))
  times+=("$(printf '%-40s %4d s  (%d min %02d s)%s' "$name" $s $((s / 60)) $((s % 60)) \
    "$([ $rc -eq 0 ] || echo "  FAILED, exit $rc")")")
  echo "test.sh: [$(date +%T)] $name: $s s" >&2
  return $rc
}
report() {
  local s=$(($(date +%s) - t0))
  times+=("$(printf '%-40s %4d s  (%d min %02d s)' "total" $s $((s / 60)) $((s % 60)))")
  echo "test.sh: stage times" >&2
  printf 'test.sh:   %s\n' "${times[@]}" >&2
}
trap report EXIT

stage "build/ configure + build" scripts/setup.sh build -DINDOORMAP_BUILD_BENCH="$bench"
stage "build/ ctest" ctest --test-dir build --output-on-failure --timeout 1200 -j "$jobs"

if [ "$sanitize" = 1 ]; then
  stage "build-san/ configure + build" \
    scripts/setup.sh build-san -DINDOORMAP_FUZZ=ON -DINDOORMAP_BUILD_BENCH=OFF
  # halt_on_error: a UBSan report fails the test instead of scrolling by. Leaks are reported at
  # exit (LeakSanitizer), in the test binaries and in the apps they run. Suppressions (third-party
  # code only, each with its reason): tests/sanitizers/.
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$PWD/tests/sanitizers/ubsan.supp"
  export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1"
  export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
  # The accuracy sweeps of tests/sanitizers/skip_tests.txt and the tests labelled "slow"
  # (tests/test_*_slow.cpp) run in build/ only (reasons there).
  skip="$(sed 's/#.*//' tests/sanitizers/skip_tests.txt | awk 'NF { printf "%s%s", s, $1; s = "|" }')"
  stage "build-san/ ctest (ASan + UBSan)" \
    ctest --test-dir build-san --output-on-failure --timeout 2400 -j "$jobs" -LE slow -E "^(${skip//./\\.})\$"
  unset UBSAN_OPTIONS ASAN_OPTIONS LSAN_OPTIONS
fi

if [ "$fuzz" = 1 ]; then
  stage "fuzz targets (scripts/fuzz.sh)" scripts/fuzz.sh
fi
echo "test.sh: [$(date +%T)] done" >&2
